// Implementation of skelconv/mesh/triangle_mesh.hpp.
#include "skelconv/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

#include "../detail/whole_files.hpp"

namespace skelconv {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary PLY is written as binary_little_endian by copying doubles");

enum class MeshFormat { ply, obj };

MeshFormat format_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".ply") return MeshFormat::ply;
  if (extension == ".obj") return MeshFormat::obj;
  throw InputError("unknown mesh format \"" + path.extension().string() + "\" (use .ply or .obj)", path.string());
}

void check_mesh(const TriangleMesh& mesh) {
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.vertices.size()) {
    throw InputError(fmt::format("mesh has {} normals for {} vertices", mesh.normals.size(), mesh.vertices.size()));
  }
  const auto vertex_count = std::int64_t(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    for (std::int32_t index : mesh.triangles[k]) {
      if (index < 0 || index >= vertex_count) {
        throw InputError(fmt::format("triangle {} has vertex index {} outside [0, {})", k, index, vertex_count));
      }
    }
  }
}

void append_raw(std::string& out, const void* data, std::size_t size) {
  out.append(static_cast<const char*>(data), size);
}

std::string ply_text(const TriangleMesh& mesh, PlyEncoding encoding) {
  const bool with_normals = !mesh.normals.empty();
  std::string out = "ply\n";
  out += encoding == PlyEncoding::binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n";
  out += "comment written by skelconv\n";
  out += fmt::format("element vertex {}\n", mesh.vertices.size());
  out += "property double x\nproperty double y\nproperty double z\n";
  if (with_normals) out += "property double nx\nproperty double ny\nproperty double nz\n";
  out += fmt::format("element face {}\n", mesh.triangles.size());
  out += "property list uchar int vertex_indices\nend_header\n";
  if (encoding == PlyEncoding::binary) {
    // The exact size: one allocation instead of a string grown by doubling
    // (a copy of everything written so far at each step).
    const std::size_t per_vertex = (with_normals ? 6 : 3) * sizeof(double);
    const std::size_t per_triangle = 1 + 3 * sizeof(std::int32_t);
    out.reserve(out.size() + mesh.vertices.size() * per_vertex + mesh.triangles.size() * per_triangle);
  }
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const Vec3& v = mesh.vertices[k];
    if (encoding == PlyEncoding::binary) {
      append_raw(out, v.data(), 3 * sizeof(double));
      if (with_normals) append_raw(out, mesh.normals[k].data(), 3 * sizeof(double));
    } else {
      out += fmt::format("{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z());
      if (with_normals) {
        const Vec3& n = mesh.normals[k];
        out += fmt::format(" {:.17g} {:.17g} {:.17g}", n.x(), n.y(), n.z());
      }
      out += '\n';
    }
  }
  for (const auto& triangle : mesh.triangles) {
    if (encoding == PlyEncoding::binary) {
      const unsigned char count = 3;
      append_raw(out, &count, 1);
      append_raw(out, triangle.data(), 3 * sizeof(std::int32_t));
    } else {
      out += fmt::format("3 {} {} {}\n", triangle[0], triangle[1], triangle[2]);
    }
  }
  return out;
}

std::string obj_text(const TriangleMesh& mesh) {
  const bool with_normals = !mesh.normals.empty();
  std::string out = "# written by skelconv\n";
  for (const Vec3& v : mesh.vertices) out += fmt::format("v {:.17g} {:.17g} {:.17g}\n", v.x(), v.y(), v.z());
  for (const Vec3& n : mesh.normals) out += fmt::format("vn {:.17g} {:.17g} {:.17g}\n", n.x(), n.y(), n.z());
  for (const auto& t : mesh.triangles) {
    // OBJ indices are 1-based; with normals, vertex k uses normal k.
    if (with_normals) {
      out += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    } else {
      out += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
  }
  return out;
}

}  // namespace

void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path, PlyEncoding ply_encoding) {
  const MeshFormat format = format_of(path);
  check_mesh(mesh);
  detail::write_file_atomically(format == MeshFormat::ply ? ply_text(mesh, ply_encoding) : obj_text(mesh), path);
}

}  // namespace skelconv
