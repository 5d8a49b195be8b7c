// codegen/straight_line_program.hpp — from GiNaC expressions to C++ statements.
//
// A StraightLineProgram is what one generated function computes: named inputs,
// an ordered list of named intermediate quantities (each a GiNaC expression of
// earlier ones), optional run-time choices between alternative forms, and the
// outputs. `emit` turns it into C++ statements and counts their operations.
//
// What emission does, in order of importance:
//  * common subexpressions: every sub-expression that occurs twice is computed
//    once into a `const T tN`;
//  * strength reduction: x^k (integer k) becomes products of memoised powers;
//    x^(k/2) uses the single sqrt(x) of its base; all divisions by the same
//    base share one reciprocal (a lone division stays a division);
//  * operation counting, on the code actually written (rules in op_count.hpp).
#pragma once

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <skelconv/kernels/op_count.hpp>

namespace skelconv::codegen {

/// A call of a hand-written helper that fills an array, whose elements are
/// then symbols of the program: `std::array<T, N> array; function(args…, array.data());`
struct ArrayCall {
  std::string array;                     ///< C++ name of the array
  std::string function;                  ///< e.g. segment_moments_beyond_end<T>
  std::vector<std::string> fixed_args;   ///< leading literal arguments (integers)
  std::vector<GiNaC::ex> args;           ///< then these expressions
  std::vector<GiNaC::symbol> elements;   ///< bound to array[0], array[1], …
  /// What one call costs (codegen/helper_costs.hpp): for a loop whose
  /// length depends on P, its longest.
  OpCount ops;
  /// The same cost at every P (a fixed Gauss rule). Alternatives that call a
  /// helper without a fixed rule are left out of generic_only programs.
  bool fixed_rule = false;
  /// The call is made only where every condition here is >= 0 (written as
  /// an Alternative's conditions are); elsewhere its elements are 0. For a
  /// result that what reads it ignores outside the guard: the call's cost
  /// is then paid only where it is read. The operation counts include it.
  std::vector<GiNaC::ex> guard = {};
};

/// One alternative form of some quantities. It is taken when every
/// condition is >= 0 (a condition ±y + m, m a number, is written as the
/// comparison of y with m, without the subtraction); the last alternative
/// of a Choice is the fallback and has no conditions.
struct Alternative {
  /// Other values for the same targets where further conditions hold, from
  /// the same steps and helper calls (so the calls are written once): e.g.
  /// G_E by parts near the segment's line and as a difference elsewhere,
  /// from one Gauss rule's moments.
  struct Refinement {
    std::vector<GiNaC::ex> conditions;  ///< all >= 0, besides the alternative's
    std::string why;                    ///< one line for the generated comment
    std::vector<GiNaC::ex> values;      ///< one per Choice target
  };
  std::vector<GiNaC::ex> conditions;
  std::string why;  ///< one line for the generated comment
  std::vector<std::pair<GiNaC::symbol, GiNaC::ex>> steps;  ///< local definitions
  std::vector<GiNaC::ex> values;  ///< one per Choice target
  std::vector<ArrayCall> calls;   ///< helper calls, after the steps
  /// Taken where its conditions hold; `values` elsewhere (and at a generic P).
  std::optional<Refinement> refinement = std::nullopt;
};

/// Quantities with several forms chosen at run time (e.g. stable rewrites
/// near the segment's line, docs/mathematics.md §2).
struct Choice {
  std::vector<GiNaC::symbol> targets;
  std::vector<Alternative> alternatives;
  size_t generic = 0;  ///< the alternative taken for P in general position
};

/// The code and the operation count of one emitted program.
struct EmittedCode {
  std::string body;     ///< C++ statements, indented by two spaces
  OpCount ops;          ///< ops on the generic path (Choice::generic everywhere)
  OpCount ops_longest;  ///< ops on the longest path through the choices
  /// generic_only: a C++ bool expression, true where the generic forms are
  /// the ones the full program would take.
  std::string generic_applies = "true";
  /// The C++ text of every input the code reads.
  std::set<std::string> inputs_read;
};

/// What `emit` writes.
enum class Forms {
  all,           ///< every alternative, chosen at run time
  generic_only,  ///< without the alternatives that call a helper with a
                 ///< loop of run-time length (fixed rules stay): code a
                 ///< compiler can vectorise, plus where it is exact
};

class StraightLineProgram {
 public:
  /// An input: a symbol read from a C++ expression such as `in.a[0]`.
  void add_input(const GiNaC::symbol& s, std::string cpp);
  /// An intermediate quantity, defined in terms of inputs and earlier ones.
  void define(const GiNaC::symbol& s, const GiNaC::ex& value);
  /// A quantity with alternative forms chosen at run time.
  void choose(Choice choice);
  /// An output: `cpp_lhs = value;` is emitted at the end.
  void add_output(std::string cpp_lhs, const GiNaC::ex& value);
  /// Declares that symbol `root` is √`square` (both defined), so the
  /// emitter writes root² as `square` and 1/square as (1/root)².
  void declare_square_root(const GiNaC::symbol& root, const GiNaC::symbol& square);

  EmittedCode emit(Forms forms = Forms::all) const;

 private:
  struct Step {
    enum class Kind { define, choose } kind;
    std::vector<GiNaC::symbol> targets;  // one for define
    GiNaC::ex value;                     // define
    Choice choice;                       // choose
  };
  std::vector<std::pair<GiNaC::symbol, std::string>> inputs_;
  std::vector<Step> steps_;
  std::vector<std::pair<std::string, GiNaC::ex>> outputs_;
  std::map<GiNaC::symbol, GiNaC::symbol, GiNaC::ex_is_less> root_of_square_;
  std::map<GiNaC::symbol, GiNaC::symbol, GiNaC::ex_is_less> square_of_root_;

  friend class Emitter;
  friend class PreparedQuantities;
};

/// The quantities of one kernel that depend on the primitive only: every
/// input `per_primitive` accepts, every definition computed from those
/// alone, and every sub-expression of the per-point code (a whole term or
/// factor, or the per-primitive terms of a sum) that reads nothing else. `per_point_part` takes them out of a
/// program, which then reads them from the array `pre` (`const T name =
/// pre[i];`); `prepare_program` computes them, once per primitive. One
/// instance serves a kernel's f, ∇f and both, so that one array holds what
/// any of the three reads: quantities are shared by name (the three programs
/// are built from fresh symbols of the same names).
class PreparedQuantities {
 public:
  explicit PreparedQuantities(std::function<bool(const std::string& cpp)> per_primitive_input)
      : per_primitive_input_(std::move(per_primitive_input)) {}

  /// `program` without its per-primitive work; its per-point inputs are
  /// read from `rename(cpp)` instead of `cpp`.
  StraightLineProgram per_point_part(const StraightLineProgram& program,
                                     const std::function<std::string(const std::string&)>& rename);

  std::size_t size() const { return fields_.size(); }
  /// The local name the per-point code gives pre[i].
  const std::string& field_name(std::size_t i) const { return fields_[i].name; }
  /// `const T name = pre[i];` for each field in `read` (EmittedCode::inputs_read), in index order.
  std::string read_fields_text(const std::set<std::string>& read) const;
  /// The program that writes `pre[i] = …;` for every field, or only for
  /// those in `only` (to count what one output needs).
  StraightLineProgram prepare_program(const std::set<std::string>* only = nullptr) const;

 private:
  struct Field {
    std::string name;
    GiNaC::ex value;  // in the canonical symbols
  };
  GiNaC::ex canonical(const GiNaC::ex& e) const;
  std::string field_for(const GiNaC::ex& e, const std::string& name);

  std::function<bool(const std::string&)> per_primitive_input_;
  std::map<std::string, GiNaC::symbol> canonical_;            // by name: the first program's symbols
  std::vector<std::pair<GiNaC::symbol, std::string>> inputs_;  // per-primitive inputs, canonical
  std::vector<std::pair<GiNaC::symbol, GiNaC::ex>> steps_;     // per-primitive definitions, canonical
  std::set<std::string> defined_;                             // names in inputs_ and steps_
  std::vector<Field> fields_;
  std::map<std::string, std::size_t> field_by_key_;  // printed canonical value → index
  int seg_count_ = 0;                                 // fields named seg0, seg1, …
  std::map<GiNaC::symbol, GiNaC::symbol, GiNaC::ex_is_less> root_of_square_;
};

}  // namespace skelconv::codegen
