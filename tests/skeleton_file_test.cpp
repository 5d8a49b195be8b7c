// The JSON skeleton reader: the schema example loads, and every kind of bad
// input is rejected with a message that names the problem and its JSON path.
#include "skelconv/skeleton/skeleton_file.hpp"

#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace skelconv {
namespace {

constexpr const char* schema_example = R"({"primitives": [
  {"type": "segment", "a": [0,0,0], "b": [1,0,0], "weight": [1, 0.5],
   "kernel": {"family": "inverse", "degree": 3}},
  {"type": "segment", "a": [0,1,0], "b": [1,1,0],
   "kernel": {"family": "cauchy", "degree": 4, "s": 2.0}},
  {"type": "segment", "a": [0,2,0], "b": [1,2,1],
   "kernel": {"family": "compact", "degree": 6, "R": 1.5}}]})";

TEST(SkeletonFile, SchemaExampleLoads) {
  const Skeleton skeleton = parse_skeleton_json(schema_example);
  ASSERT_EQ(skeleton.size(), 3u);
  const Segment& first = std::get<Segment>(skeleton.primitives()[0]);
  EXPECT_EQ(first.kernel().family, KernelFamily::inverse);
  EXPECT_EQ(first.kernel().degree, 3);
  EXPECT_EQ(first.weight_degree(), 1);
  EXPECT_EQ(first.b(), Vec3(1, 0, 0));
  const Segment& second = std::get<Segment>(skeleton.primitives()[1]);
  EXPECT_EQ(second.kernel().s, 2.0);
  EXPECT_EQ(second.weight_degree(), 0);  // default weight [1]
  const Segment& third = std::get<Segment>(skeleton.primitives()[2]);
  EXPECT_EQ(third.kernel().family, KernelFamily::compact);
  EXPECT_EQ(third.kernel().R, 1.5);
  EXPECT_TRUE(std::isfinite(skeleton.value(Vec3(0.5, 0.5, 0.5))));
}

TEST(SkeletonFile, EmptyPrimitiveListIsAnEmptySkeleton) {
  EXPECT_TRUE(parse_skeleton_json(R"({"primitives": []})").empty());
}

/// A segment primitive with `kernel` and extra members `extra` (",..."),
/// wrapped as primitives[0].
std::string one_segment(const std::string& kernel, const std::string& extra = "",
                        const std::string& a = "[0,0,0]", const std::string& b = "[1,0,0]") {
  return R"({"primitives": [{"type": "segment", "a": )" + a + R"(, "b": )" + b + R"(, "kernel": )" + kernel +
         extra + "}]}";
}

/// Expects InputError whose full message is `message`.
void expect_error(const std::string& json, const std::string& message) {
  try {
    parse_skeleton_json(json);
    ADD_FAILURE() << "accepted: " << json;
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), message) << json;
  }
}

const std::string inverse3 = R"({"family": "inverse", "degree": 3})";

TEST(SkeletonFileErrors, MalformedJson) {
  expect_error(R"({"primitives": [}")",
               "malformed JSON: parse error at line 1, column 17: syntax error while parsing value - "
               "unexpected '}'; expected '[', '{', or a literal");
  expect_error("", "malformed JSON: parse error at line 1, column 1: syntax error while parsing value - "
                   "unexpected end of input; expected '[', '{', or a literal");
  expect_error("{\"primitives\": [],\n}",
               "malformed JSON: parse error at line 2, column 1: syntax error while parsing object key - "
               "unexpected '}'; expected string literal");
}

TEST(SkeletonFileErrors, DocumentShape) {
  expect_error("[]", "the document must be an object {\"primitives\": [...]}, got an array []");
  expect_error("{}", "missing field \"primitives\"");
  expect_error(R"({"primitives": {}})", "primitives: must be an array, got an object");
  expect_error(R"({"primitives": [], "comment": "x"})", "unknown field \"comment\" (allowed: \"primitives\", \"iso\")");
  expect_error(R"({"primitives": [3]})", "primitives[0]: must be an object, got 3");
}

TEST(SkeletonFileErrors, MissingFields) {
  expect_error(R"({"primitives": [{"a": [0,0,0]}]})", "primitives[0]: missing field \"type\"");
  expect_error(R"({"primitives": [{"type": "segment", "b": [1,0,0], "kernel": {}}]})",
               "primitives[0]: missing field \"a\"");
  expect_error(R"({"primitives": [{"type": "segment", "a": [0,0,0], "b": [1,0,0]}]})",
               "primitives[0]: missing field \"kernel\"");
  expect_error(one_segment(R"({"family": "inverse"})"), "primitives[0].kernel: missing field \"degree\"");
  expect_error(one_segment(R"({"degree": 3})"), "primitives[0].kernel: missing field \"family\"");
  expect_error(one_segment(R"({"family": "cauchy", "degree": 3})"), "primitives[0].kernel: missing field \"s\"");
  expect_error(one_segment(R"({"family": "compact", "degree": 3})"), "primitives[0].kernel: missing field \"R\"");
}

TEST(SkeletonFileErrors, UnknownNames) {
  expect_error(one_segment(inverse3, R"(, "wieght": [1])"),
               "primitives[0]: unknown field \"wieght\" for a segment "
               "(allowed: \"type\", \"a\", \"b\", \"weight\", \"kernel\")");
  expect_error(one_segment(R"({"family": "cauchy", "degree": 3, "s": 1, "R": 2})"),
               "primitives[0].kernel: unknown field \"R\" for the cauchy family "
               "(allowed: \"family\", \"degree\", \"s\")");
  expect_error(one_segment(R"({"family": "inverse", "degree": 3, "s": 1})"),
               "primitives[0].kernel: unknown field \"s\" for the inverse family (allowed: \"family\", \"degree\")");
  expect_error(one_segment(R"({"family": "gauss", "degree": 3})"),
               "primitives[0].kernel.family: unknown family \"gauss\" "
               "(supported: \"inverse\", \"cauchy\", \"compact\", \"soft\", \"wyvill\", \"ferley\", "
               "\"gaussian\", \"polynomial\")");
  // A point-only family (its trait's `primitives`) on a segment.
  expect_error(one_segment(R"({"family": "ferley", "e": 0.5, "R": 1})"),
               "primitives[0].kernel.family: the ferley family has no closed form on a segment (it is defined on "
               "points only); a segment takes \"inverse\", \"cauchy\", \"compact\", \"soft\", \"wyvill\", "
               "\"gaussian\"");
  expect_error(R"({"primitives": [{"type": "triangle"}]})",
               "primitives[0].type: unknown primitive type \"triangle\" (supported: \"segment\", \"polygon\", \"scalis_segment\", \"scalis_triangle\", \"point\")");
}

TEST(SkeletonFileErrors, DuplicateFields) {
  expect_error(one_segment(R"({"family": "inverse", "degree": 3, "degree": 4})"),
               "primitives[0].kernel: duplicate field \"degree\"");
  expect_error(R"({"primitives": [], "primitives": []})", "duplicate field \"primitives\"");
}

TEST(SkeletonFileErrors, WrongTypes) {
  expect_error(one_segment(inverse3, "", R"("origin")"),
               "primitives[0].a: must be a point [x, y, z] (an array of 3 numbers), got a string \"origin\"");
  expect_error(one_segment(inverse3, "", "[0,0]"),
               "primitives[0].a: must be a point [x, y, z] (an array of 3 numbers), got an array [0,0]");
  expect_error(one_segment(inverse3, "", "[0,null,0]"), "primitives[0].a[1]: must be a number, got null");
  expect_error(one_segment(R"({"family": "inverse", "degree": "3"})"),
               "primitives[0].kernel.degree: must be a number, got a string \"3\"");
  expect_error(one_segment(R"({"family": "inverse", "degree": 3.5})"),
               "primitives[0].kernel.degree: must be an integer, got 3.5");
  expect_error(one_segment(R"({"family": 1, "degree": 3})"), "primitives[0].kernel.family: must be a string, got 1");
  expect_error(one_segment(inverse3, R"(, "weight": 1)"),
               "primitives[0].weight: must be an array of numbers, got 1");
  expect_error(one_segment(inverse3, R"(, "weight": [1, true])"),
               "primitives[0].weight[1]: must be a number, got a boolean true");
}

TEST(SkeletonFileErrors, NumbersThatOverflowDouble) {
  // JSON has no NaN or Infinity literal; 1e999 is the way to write one.
  expect_error(one_segment(inverse3, "", "[0, 1e999, 0]"),
               "primitives[0].a[1]: number overflow parsing '1e999' (too large for double precision)");
  expect_error(one_segment(R"({"family": "compact", "degree": 4, "R": -1e400})"),
               "primitives[0].kernel.R: number overflow parsing '-1e400' (too large for double precision)");
}

TEST(SkeletonFileErrors, ValuesCheckedByTheSegment) {
  expect_error(one_segment(inverse3, "", "[1,2,3]", "[1,2,3]"),
               "primitives[0]: degenerate segment: a and b are the same point (1, 2, 3)");
  expect_error(one_segment(R"({"family": "compact", "degree": 6, "R": -1})"),
               "primitives[0].kernel.R: must be > 0, got -1");
  expect_error(one_segment(R"({"family": "cauchy", "degree": 6, "s": 0})"),
               "primitives[0].kernel.s: must be > 0, got 0");
  expect_error(one_segment(inverse3, R"(, "weight": [1, 2, 3, 4, 5])"),
               "primitives[0].weight: at most 4 coefficients (w(t) of degree <= 3), got 5");
  try {
    parse_skeleton_json(one_segment(R"({"family": "inverse", "degree": 99})"));
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_TRUE(std::string(error.what()).starts_with(
        "primitives[0].kernel.degree: unsupported degree 99 for the inverse family; supported: "))
        << error.what();
  }
}

TEST(SkeletonFileErrors, ErrorsInLaterPrimitivesNameTheirIndex) {
  const std::string json = R"({"primitives": [
    {"type": "segment", "a": [0,0,0], "b": [1,0,0], "kernel": {"family": "inverse", "degree": 3}},
    {"type": "segment", "a": [0,1,0], "b": [1,1,0], "kernel": {"family": "cauchy", "degree": 4, "s": 2.0}},
    {"type": "segment", "a": [0,2,0], "b": [1,2,1], "kernel": {"family": "compact", "degree": 6, "R": -1}}]})";
  expect_error(json, "primitives[2].kernel.R: must be > 0, got -1");
}

// --- Polygons ---------------------------------------------------------------

/// A polygon primitive with `vertices` and `kernel`, extra members `extra`,
/// after one segment: primitives[1].
std::string segment_then_polygon(const std::string& vertices, const std::string& kernel = inverse3,
                                 const std::string& extra = "") {
  return R"({"primitives": [{"type": "segment", "a": [0,0,0], "b": [1,0,0], "kernel": )" + inverse3 +
         R"(}, {"type": "polygon", "vertices": )" + vertices + R"(, "kernel": )" + kernel + extra + "}]}";
}

const std::string unit_square = "[[0,0,0], [1,0,0], [1,1,0], [0,1,0]]";

TEST(SkeletonFile, PolygonLoads) {
  const Skeleton skeleton = parse_skeleton_json(
      segment_then_polygon(unit_square, R"({"family": "compact", "degree": 6, "R": 1.5})"));
  ASSERT_EQ(skeleton.size(), 2u);
  const Polygon& polygon = std::get<Polygon>(skeleton.primitives()[1]);
  EXPECT_EQ(polygon.vertices().size(), 4u);
  EXPECT_EQ(polygon.kernel().family, KernelFamily::compact);
  EXPECT_EQ(polygon.kernel().degree, 6);
  EXPECT_EQ(polygon.kernel().R, 1.5);
  EXPECT_EQ(polygon.normal(), Vec3(0, 0, 1));
  EXPECT_EQ(polygon.area(), 1.0);
}

TEST(SkeletonFileErrors, PolygonShapeOfTheDocument) {
  expect_error(segment_then_polygon(unit_square, inverse3, R"(, "weight": [1])"),
               "primitives[1]: unknown field \"weight\" for a polygon (allowed: \"type\", \"vertices\", \"kernel\")");
  expect_error(R"({"primitives": [{"type": "polygon", "kernel": )" + inverse3 + "}]}",
               "primitives[0]: missing field \"vertices\"");
  expect_error(R"({"primitives": [{"type": "polygon", "vertices": )" + unit_square + "}]}",
               "primitives[0]: missing field \"kernel\"");
  expect_error(segment_then_polygon("[0,0,0]"),
               "primitives[1].vertices[0]: must be a point [x, y, z] (an array of 3 numbers), got 0");
  expect_error(segment_then_polygon("3"), "primitives[1].vertices: must be an array of points [[x, y, z], ...], got 3");
  expect_error(segment_then_polygon("[[0,0,0], [1,0,0], [1,1,0], [0,1,1e999]]"),
               "primitives[1].vertices[3][2]: number overflow parsing '1e999' (too large for double precision)");
  expect_error(segment_then_polygon("[[0,0,0], [1,0,0], [1,1,0], [0,\"1\",0]]"),
               "primitives[1].vertices[3][1]: must be a number, got a string \"1\"");
  expect_error(segment_then_polygon(unit_square, R"({"family": "inverse", "degree": 3, "degree": 4})"),
               "primitives[1].kernel: duplicate field \"degree\"");
}

TEST(SkeletonFileErrors, ValuesCheckedByThePolygon) {
  expect_error(segment_then_polygon("[[0,0,0], [1,0,0]]"),
               "primitives[1].vertices: a polygon needs at least 3 vertices, got 2");
  expect_error(segment_then_polygon("[[0,0,0], [1,0,0], [1,1,0], [0,0,0]]"),
               "primitives[1].vertices[3]: the last vertex repeats the first one (0, 0, 0): the boundary closes by "
               "itself (from the last vertex back to the first), list each vertex once");
  expect_error(segment_then_polygon(unit_square, R"({"family": "inverse", "degree": 2})"),
               "primitives[1].kernel.degree: degree 2 of the inverse family is not available on a polygon: the "
               "contour formula of the polygon closed forms (docs/mathematics.md §3, Hubert 2012 §6) excludes it; supported: 3..12");
  expect_error(segment_then_polygon(unit_square, R"({"family": "compact", "degree": 4, "R": 0})"),
               "primitives[1].kernel.R: must be > 0, got 0");
}

TEST(SkeletonFile, ScalisTriangleLoads) {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
    {"type": "scalis_triangle", "vertices": [[0,0,0], [2,0,0], [0,1.5,0.3]], "radius": [0.2, 0.5, 0.3],
     "kernel": {"family": "compact", "degree": 3, "sigma": 2.5}, "iso": 0.7},
    {"type": "scalis_triangle", "vertices": [[0,3,0], [2,3,0], [0,5,0]], "radius": [0.4, 0.4, 0.4],
     "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5}}]})");
  ASSERT_EQ(skeleton.size(), 2u);
  const ScalisTriangle& varying = std::get<ScalisTriangle>(skeleton.primitives()[0]);
  EXPECT_EQ(varying.vertices()[2], Vec3(0, 1.5, 0.3));
  EXPECT_EQ(varying.radii()[1], 0.5);
  EXPECT_EQ(varying.kernel().family, KernelFamily::compact);
  EXPECT_EQ(varying.kernel().degree, 3);
  EXPECT_EQ(varying.kernel().sigma, 2.5);
  EXPECT_EQ(varying.iso(), 0.7);
  EXPECT_FALSE(varying.uses_closed_form());
  const ScalisTriangle& constant = std::get<ScalisTriangle>(skeleton.primitives()[1]);
  EXPECT_EQ(constant.iso(), 1.0);  // the default
  EXPECT_TRUE(constant.uses_closed_form());
}

TEST(SkeletonFileErrors, ScalisTriangleShapeAndValues) {
  const std::string kernel = R"("kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5})";
  const std::string triangle = R"({"primitives": [{"type": "scalis_triangle", )";
  expect_error(triangle + R"("vertices": [[0,0,0], [1,0,0]], "radius": [1, 1, 1], )" + kernel + "}]}",
               "primitives[0].vertices: must be the 3 vertices [[x, y, z], [x, y, z], [x, y, z]] (an array of 3 "
               "points), got an array [[0,0,0],[1,0,0]]");
  expect_error(triangle + R"("vertices": [[0,0,0], [1,0,0], [0,1,0]], "radius": [1, 1], )" + kernel + "}]}",
               "primitives[0].radius: must be the radii [tau0, tau1, tau2] at the vertices (an array of 3 numbers), "
               "got an array [1,1]");
  expect_error(triangle + R"("vertices": [[0,0,0], [1,0,0], [0,1,0]], "radius": [1, -1, 1], )" + kernel + "}]}",
               "primitives[0].radius[1]: must be >= 0, got -1");
  expect_error(triangle + R"("vertices": [[0,0,0], [1,0,0], [0,1,0]], "radius": [1, 1, 1], "s": 2, )" + kernel +
                   "}]}",
               "primitives[0]: unknown field \"s\" for a scalis_triangle (allowed: \"type\", \"vertices\", "
               "\"radius\", \"kernel\", \"iso\")");
}

// --- Point primitives, blend nodes and iso (docs/cli_blends.md) ---------------

constexpr const char* cauchy_kernel = R"({"family": "cauchy", "degree": 4, "s": 2})";

/// A point primitive with extra members `extra` (",...").
std::string point(const std::string& extra = "", const std::string& kernel = cauchy_kernel) {
  return R"({"type": "point", "center": [0, 0, 0], "kernel": )" + kernel + extra + "}";
}

/// A document whose primitives[0] is `element`, with top-level `extra`.
std::string document(const std::string& element, const std::string& extra = "") {
  return R"({"primitives": [)" + element + "]" + extra + "}";
}

TEST(SkeletonFile, BlendTreeLoads) {
  const Skeleton skeleton = parse_skeleton_json(R"({"iso": 0.5, "primitives": [
    {"type": "point", "center": [0, 0, 0], "kernel": {"family": "compact", "degree": 4, "R": 1}, "weight": 2},
    {"blend": "union", "children": [
      {"blend": "super_elliptic", "t": 2, "r": [0.2, 0.3], "children": [
        {"type": "point", "center": [1, 0, 0], "kernel": {"family": "cauchy", "degree": 4, "s": 2}},
        {"type": "segment", "a": [0, 1, 0], "b": [1, 1, 0], "kernel": {"family": "inverse", "degree": 3}}]},
      {"blend": "sum", "weights": [1.5], "children": [
        {"type": "point", "center": [3, 0, 0], "kernel": {"family": "inverse", "degree": 2}}]}]}]})");
  EXPECT_EQ(skeleton.iso(), 0.5);
  ASSERT_EQ(skeleton.size(), 4u);
  EXPECT_EQ(std::get<PointPrimitive>(skeleton.primitives()[0]).weight(), 2.0);
  EXPECT_EQ(skeleton.location(2), "primitives[1].children[0].children[1]");
  EXPECT_EQ(skeleton.location(3), "primitives[1].children[1].children[0]");
  EXPECT_EQ(skeleton.blend(2).iso, 0.5);  // inherited from the file
  EXPECT_EQ(skeleton.blend(2).r, (std::vector<double>{0.2, 0.3}));
  EXPECT_EQ(skeleton.value(Vec3(3, 0, 0)), std::numeric_limits<double>::infinity());
  EXPECT_EQ(parse_skeleton_json(R"({"primitives": []})").iso(), 1.0);  // the default
}

TEST(SkeletonFileErrors, PointPrimitives) {
  expect_error(document(point(R"(, "weight": 0)")), "primitives[0].weight: must be non-zero: the primitive would "
                                                    "contribute nothing");
  expect_error(document(point(R"(, "weight": [1, 2])")),
               "primitives[0].weight: must be a number (a point's weight is a scalar factor), got an array [1,2]");
  expect_error(document(point(R"(, "radius": 1)")),
               "primitives[0]: unknown field \"radius\" for a point (allowed: \"type\", \"center\", \"kernel\", "
               "\"weight\")");
  expect_error(document(R"({"type": "point", "kernel": {"family": "inverse", "degree": 2}})"),
               "primitives[0]: missing field \"center\"");
  expect_error(document(point("", R"({"family": "compact", "degree": 1, "R": 1})")),
               "primitives[0].kernel.degree: unsupported degree 1 for the compact family on a point; supported: "
               "2..16");
  expect_error(document(point("", R"({"family": "cauchy", "degree": 2, "s": -1})")),
               "primitives[0].kernel.s: must be > 0, got -1");
}

TEST(SkeletonFileErrors, BlendParameters) {
  const std::string two = "\"children\": [" + point() + ", " + point() + "]";
  expect_error(document(R"({"blend": "super_elliptic", "t": 0, "r": 0.5, )" + two + "}"),
               "primitives[0].t: must be > 0, got 0");
  expect_error(document(R"({"blend": "super_elliptic", "t": -2, "r": 0.5, )" + two + "}"),
               "primitives[0].t: must be > 0, got -2");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": 0, )" + two + "}"),
               "primitives[0].r: must be > 0, got 0");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": [0.5, -1], )" + two + "}"),
               "primitives[0].r[1]: must be > 0, got -1");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": [0.5, 1, 2], )" + two + "}"),
               "primitives[0].r: must have one entry per child (2) or be a single number, got 3");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": 1, "iso": 0, )" + two + "}"),
               "primitives[0].iso: must be > 0, got 0");
  expect_error(document(R"({"blend": "super_elliptic", "r": 1, )" + two + "}"),
               "primitives[0]: missing field \"t\"");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": 1, "angle_weighted": true, "children": [)" +
                        point() + "]}"),
               "primitives[0].angle_weighted: the angle-weighted super_elliptic blend is binary: it needs exactly 2 "
               "children, got 1");
  expect_error(document(R"({"blend": "super_elliptic", "t": 2, "r": 1, "angle_weighted": 1, )" + two + "}"),
               "primitives[0].angle_weighted: must be true or false, got 1");
  expect_error(document(R"({"blend": "sum", "weights": [1], )" + two + "}"),
               "primitives[0].weights: must have one entry per child (2), got 1");
  expect_error(document(R"({"blend": "sum", "weights": [1, 0], )" + two + "}"),
               "primitives[0].weights[1]: must be non-zero: a zero weight removes the child");
}

TEST(SkeletonFileErrors, BlendShape) {
  expect_error(document(R"({"blend": "union", "children": []})"),
               "primitives[0].children: a union blend needs at least one child");
  expect_error(document(R"({"blend": "smooth_union", "children": [)" + point() + "]}"),
               "primitives[0].blend: unknown blend \"smooth_union\" (supported: \"sum\", \"union\", "
               "\"super_elliptic\")");
  expect_error(document(R"({"blend": "union", "t": 2, "children": [)" + point() + "]}"),
               "primitives[0]: unknown field \"t\" for a union blend (allowed: \"blend\", \"children\")");
  expect_error(document(R"({"blend": "sum"})"), "primitives[0]: missing field \"children\"");
  expect_error(document(R"({"blend": "sum", "children": {}})"),
               "primitives[0].children: must be an array of primitives and blend nodes, got an object");
  expect_error(document(R"({"children": []})"),
               "primitives[0]: missing field \"blend\" (a node with \"children\" is a blend node)");
}

TEST(SkeletonFileErrors, ErrorsDeepInTheTreeReadLikeTheFile) {
  expect_error(document(point() + R"(, {"blend": "union", "children": [{"type": "segment", "a": [0,0,0],
                 "b": [1,0,0], "kernel": {"family": "compact", "degree": 4, "R": -1}}]})"),
               "primitives[1].children[0].kernel.R: must be > 0, got -1");
  expect_error(document(R"({"blend": "sum", "children": [{"blend": "union", "children": [)" + point() + ", " +
                        point(R"(, "wieght": 2)") + "]}]}"),
               "primitives[0].children[0].children[1]: unknown field \"wieght\" for a point (allowed: \"type\", "
               "\"center\", \"kernel\", \"weight\")");
}

TEST(SkeletonFileErrors, FileIso) {
  expect_error(document(point(), R"(, "iso": 0)"), "iso: must be > 0, got 0");
  expect_error(document(point(), R"(, "iso": -1)"), "iso: must be > 0, got -1");
  expect_error(document(point(), R"(, "iso": "1")"), "iso: must be a number, got a string \"1\"");
}

TEST(SkeletonFileErrors, FilesThatCannotBeRead) {
  try {
    load_skeleton_file("/nonexistent/skeleton.json");
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/skeleton.json: cannot open: No such file or directory");
  }
  EXPECT_THROW(load_skeleton_file("/"), InputError);
}

}  // namespace
}  // namespace skelconv
