// codegen/straight_line_program.cpp — emission with CSE, strength reduction
// and operation counting. See straight_line_program.hpp for what it does.
#include "straight_line_program.hpp"

#include <algorithm>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "helper_costs.hpp"

namespace skelconv::codegen {

using GiNaC::ex;
using GiNaC::ex_is_less;
using GiNaC::is_a;
using GiNaC::numeric;
using GiNaC::symbol;

void StraightLineProgram::add_input(const symbol& s, std::string cpp) {
  inputs_.emplace_back(s, std::move(cpp));
}

void StraightLineProgram::define(const symbol& s, const ex& value) {
  steps_.push_back({Step::Kind::define, {s}, value, {}});
}

void StraightLineProgram::choose(Choice choice) {
  if (choice.alternatives.empty()) throw std::logic_error("choose: no alternative");
  for (const auto& alt : choice.alternatives)
    if (alt.values.size() != choice.targets.size()) throw std::logic_error("choose: one value per target");
  const auto targets = choice.targets;
  steps_.push_back({Step::Kind::choose, targets, 0, std::move(choice)});
}

void StraightLineProgram::add_output(std::string cpp_lhs, const ex& value) {
  outputs_.emplace_back(std::move(cpp_lhs), value);
}

void StraightLineProgram::declare_square_root(const symbol& root, const symbol& square) {
  root_of_square_.emplace(square, root);
  square_of_root_.emplace(root, square);
}

namespace {

// C++ text of an emitted expression and its precedence, so that operands are
// parenthesised only where C++ needs it.
struct Text {
  std::string s;
  enum Precedence { sum = 1, product = 2, atom = 3 } precedence;
};

// Whether e calls J_downward or J_upward_compact (include/skelconv/
// stable_recurrence.hpp): loops whose length depends on P.
bool calls_loop_helper(const ex& e) {
  if (is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name == "J_downward" || name == "J_upward_compact") return true;
  }
  for (size_t i = 0; i < e.nops(); ++i)
    if (calls_loop_helper(e.op(i))) return true;
  return false;
}

// Every symbol e reads, into `out`.
void collect_symbols(const ex& e, std::set<symbol, ex_is_less>& out) {
  if (is_a<symbol>(e)) out.insert(GiNaC::ex_to<symbol>(e));
  for (size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

// An identifier or `in.x[i]`: needs no temporary of its own.
bool is_plain_name(const std::string& s) {
  static const std::regex name(R"([A-Za-z_][A-Za-z0-9_]*(\.[a-z]+)?(\[[0-9]+\])?)");
  return std::regex_match(s, name);
}

std::string as_divisor(const Text& t) { return t.precedence >= Text::atom ? t.s : "(" + t.s + ")"; }

std::string as_factor(const Text& t) { return t.precedence >= Text::product ? t.s : "(" + t.s + ")"; }

bool is_half_integer(const numeric& e) { return !e.is_integer() && (2 * e).is_integer(); }

}  // namespace

// Emits one StraightLineProgram. One Emitter per program: temporaries are
// numbered from t0 in the order they are first needed, so the output is a
// deterministic function of the program.
class Emitter {
 public:
  Emitter(const StraightLineProgram& program, Forms forms) : program_(program), forms_(forms) {}

  EmittedCode run() {
    find_live_steps();
    count_uses();
    scopes_.emplace_back();
    for (const auto& [s, cpp] : program_.inputs_) {
      names_[s] = cpp;
      input_symbols_.insert(s);
    }
    for (size_t i = 0; i < program_.steps_.size(); ++i) {
      const auto& step = program_.steps_[i];
      if (!live_[i]) continue;
      if (step.kind == StraightLineProgram::Step::Kind::define) {
        define(step.targets[0], step.value);
      } else {
        emit_choice(live_choices_.at(i));
      }
    }
    for (const auto& [lhs, value] : program_.outputs_) line(lhs + " = " + emit(value).s + ";");
    return {body_.str(), scopes_.back().generic, scopes_.back().longest,
            special_forms_.empty() ? "true" : "!(" + special_forms_ + ")", inputs_read_};
  }

 private:
  struct Scope {
    std::map<ex, std::string, ex_is_less> memo;  // emitted sub-expressions
    OpCount generic;  // ops since the scope began, on the generic path
    OpCount longest;  // ops since the scope began, on the longest path
  };

  // ---- pre-pass: which steps the outputs need (dead steps are not written)
  void find_live_steps() {
    std::set<symbol, ex_is_less> needed;
    for (const auto& [lhs, value] : program_.outputs_) collect_symbols(value, needed);
    live_.assign(program_.steps_.size(), false);
    for (size_t i = program_.steps_.size(); i-- > 0;) {
      const auto& step = program_.steps_[i];
      if (std::none_of(step.targets.begin(), step.targets.end(), [&](const symbol& t) { return needed.count(t); }))
        continue;
      live_[i] = true;
      if (step.kind == StraightLineProgram::Step::Kind::define) {
        collect_symbols(step.value, needed);
      } else {
        // Only the targets something reads: the others, and their values in
        // every alternative, are not written.
        Choice& pruned = live_choices_[i] = step.choice;
        pruned.targets.clear();
        for (auto& alt : pruned.alternatives) {
          alt.values.clear();
          if (alt.refinement) alt.refinement->values.clear();
        }
        for (size_t j = 0; j < step.choice.targets.size(); ++j) {
          if (!needed.count(step.choice.targets[j])) continue;
          pruned.targets.push_back(step.choice.targets[j]);
          for (size_t a = 0; a < pruned.alternatives.size(); ++a) {
            const Alternative& full = step.choice.alternatives[a];
            pruned.alternatives[a].values.push_back(full.values[j]);
            if (full.refinement) pruned.alternatives[a].refinement->values.push_back(full.refinement->values[j]);
          }
        }
        for (const auto& alt : pruned.alternatives)
          for_each_expression(alt, [&](const ex& e) { collect_symbols(e, needed); });
      }
    }
  }

  // Every expression an alternative computes: conditions, steps, call
  // arguments, values, and its refinement's conditions and values.
  template <class Visit>
  static void for_each_expression(const Alternative& alt, Visit&& visit) {
    for (const ex& c : alt.conditions) visit(c);
    for (const auto& [s, v] : alt.steps) visit(v);
    for (const ArrayCall& call : alt.calls) {
      for (const ex& c : call.guard) visit(c);
      for (const ex& a : call.args) visit(a);
    }
    for (const ex& v : alt.values) visit(v);
    if (alt.refinement) {
      for (const ex& c : alt.refinement->conditions) visit(c);
      for (size_t j = 0; j < alt.refinement->values.size(); ++j)  // emit_refinement writes shared ones once
        if (!alt.refinement->values[j].is_equal(alt.values[j])) visit(alt.refinement->values[j]);
    }
  }

  // ---- pre-pass: how often each sub-expression and each reciprocal is used
  void count_uses() {
    auto visit_all = [&](const ex& e) { visit(e); };
    for (size_t i = 0; i < program_.steps_.size(); ++i) {
      const auto& step = program_.steps_[i];
      if (!live_[i]) continue;
      if (step.kind == StraightLineProgram::Step::Kind::define) {
        visit_all(step.value);
      } else {
        for (const auto& alt : live_choices_.at(i).alternatives) for_each_expression(alt, visit_all);
      }
    }
    for (const auto& [lhs, value] : program_.outputs_) visit_all(value);
  }

  void visit(const ex& e) {
    if (is_a<symbol>(e) || is_a<numeric>(e)) return;
    if (is_a<GiNaC::power>(e)) {
      const ex& expo = e.op(1);
      if (is_a<numeric>(expo) && GiNaC::ex_to<numeric>(expo).is_negative()) ++reciprocal_uses_[e.op(0)];
    }
    if (++uses_[e] > 1) return;  // its children were counted the first time
    for (size_t i = 0; i < e.nops(); ++i) visit(e.op(i));
  }

  // `const T name = value;`, or just the name when emitting the value already
  // had to make a temporary for it.
  void define(const symbol& target, const ex& value) {
    const std::string name = target.get_name();
    pending_name_ = name;
    pending_value_ = value;
    const Text t = emit(value);
    if (t.s != name) line("const T " + name + " = " + t.s + ";");
    pending_name_.clear();
    names_[target] = name;
  }

  // ---- output helpers
  void line(const std::string& s) { body_ << std::string(2 * (scopes_.size()), ' ') << s << '\n'; }
  void count(int OpCount::*field) {
    ++(scopes_.back().generic.*field);
    ++(scopes_.back().longest.*field);
  }

  const std::string* find_memo(const ex& e) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto found = it->memo.find(e);
      if (found != it->memo.end()) return &found->second;
    }
    return nullptr;
  }

  // A new `const T` for `text`, which computes `key`. A definition step's own
  // value takes the step's name instead of a tN.
  std::string new_temp(const std::string& text, const ex& key) {
    std::string name;
    if (!pending_name_.empty() && key.is_equal(pending_value_)) {
      name = pending_name_;
      pending_name_.clear();
    } else {
      name = "t" + std::to_string(next_temp_++);
    }
    line("const T " + name + " = " + text + ";");
    return name;
  }

  // A name for e, computing it into a temporary if it is not one already.
  std::string named(const ex& e) {
    if (const std::string* m = find_memo(e)) return *m;
    const Text t = emit_uncached(e);
    if (is_a<symbol>(e) || is_plain_name(t.s)) {
      if (!is_a<symbol>(e)) scopes_.back().memo[e] = t.s;
      return t.s;
    }
    const std::string name = new_temp(t.s, e);
    scopes_.back().memo[e] = name;
    return name;
  }

  // ---- expression emission
  Text emit(const ex& e) {
    if (const std::string* m = find_memo(e)) return {*m, Text::atom};
    if (is_a<symbol>(e) || is_a<numeric>(e)) return emit_uncached(e);
    auto u = uses_.find(e);
    if (u != uses_.end() && u->second > 1) return {named(e), Text::atom};
    return emit_uncached(e);
  }

  Text emit_uncached(const ex& e) {
    if (is_a<symbol>(e)) {
      auto it = names_.find(GiNaC::ex_to<symbol>(e));
      if (it == names_.end()) throw std::logic_error("symbol used before definition: " + GiNaC::ex_to<symbol>(e).get_name());
      if (input_symbols_.count(GiNaC::ex_to<symbol>(e))) inputs_read_.insert(it->second);
      return {it->second, Text::atom};
    }
    if (is_a<numeric>(e)) return constant(GiNaC::ex_to<numeric>(e));
    if (is_a<GiNaC::add>(e)) return emit_sum(e);
    if (is_a<GiNaC::mul>(e)) return emit_product(e);
    if (is_a<GiNaC::power>(e)) {
      std::string p = power(e.op(0), GiNaC::ex_to<numeric>(e.op(1)));
      const bool name = is_plain_name(p);
      return {std::move(p), name ? Text::atom : Text::product};
    }
    if (is_a<GiNaC::function>(e)) return emit_call(e);
    std::ostringstream os;
    os << e;
    throw std::logic_error("cannot emit expression " + os.str());
  }

  static Text constant(const numeric& c) {
    if (!c.is_rational()) throw std::logic_error("non-rational constant");
    std::ostringstream num_text, den_text;
    num_text << c.numer();
    den_text << c.denom();
    const std::string num = num_text.str(), den = den_text.str();
    if (den == "1") return {"T(" + num + ")", Text::atom};
    return {"(T(" + num + ") / T(" + den + "))", Text::atom};  // folded: not counted
  }

  Text emit_sum(const ex& e) {
    // Positive terms first, so that B − A reads as `b - a`, not `-a + b`.
    std::vector<std::pair<bool, ex>> terms;
    for (size_t i = 0; i < e.nops(); ++i) terms.push_back(split_sign(e.op(i)));
    std::stable_partition(terms.begin(), terms.end(), [](const auto& t) { return !t.first; });
    std::string s;
    for (size_t i = 0; i < terms.size(); ++i) {
      auto [negative, magnitude] = terms[i];
      const Text term = emit(magnitude);
      if (i == 0) {
        s = negative ? "-" + as_factor(term) : term.s;
      } else {
        s += negative ? " - " + as_factor(term) : " + " + term.s;
        count(&OpCount::add);
      }
    }
    return {s, Text::sum};
  }

  // A term with a negative numeric coefficient is written as a subtraction.
  static std::pair<bool, ex> split_sign(const ex& term) {
    if (is_a<numeric>(term) && GiNaC::ex_to<numeric>(term).is_negative()) return {true, -term};
    if (is_a<GiNaC::mul>(term)) {
      const ex coeff = term.op(term.nops() - 1);  // GiNaC keeps the coefficient last
      if (is_a<numeric>(coeff) && GiNaC::ex_to<numeric>(coeff).is_negative()) return {true, -term};
    }
    return {false, term};
  }

  Text emit_product(const ex& e) {
    numeric coefficient = 1;
    std::vector<ex> numerator, denominator;  // denominator holds x^k for x^-k
    for (size_t i = 0; i < e.nops(); ++i) {
      const ex& f = e.op(i);
      if (is_a<numeric>(f)) {
        coefficient *= GiNaC::ex_to<numeric>(f);
      } else if (is_a<GiNaC::power>(f) && GiNaC::ex_to<numeric>(f.op(1)).is_negative() &&
                 reciprocal_uses_[f.op(0)] <= 1 && !find_memo(f)) {
        denominator.push_back(GiNaC::pow(f.op(0), -f.op(1)));  // a lone division stays a division
      } else {
        numerator.push_back(f);
      }
    }
    std::string s;
    bool negative = coefficient.is_negative();
    if (negative) coefficient = -coefficient;
    auto multiply = [&](const std::string& factor) {
      if (s.empty()) {
        s = factor;
      } else {
        s += " * " + factor;
        count(&OpCount::mul);
      }
    };
    if (coefficient != 1) multiply(constant(coefficient).s);
    for (const ex& f : numerator) multiply(as_factor(emit(f)));
    if (s.empty()) s = "T(1)";
    for (const ex& d : denominator) {
      s += " / " + as_divisor(emit(d));
      count(&OpCount::div);
    }
    return {negative ? "-" + s : s, Text::product};
  }

  Text emit_call(const ex& e) {
    const std::string fn = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const bool helper = fn == "J_downward" || fn == "J_upward_compact";  // include/skelconv/detail/stable_recurrence.hpp
    std::string args;
    for (size_t i = 0; i < e.nops(); ++i) {
      if (i) args += ", ";
      // A helper's first argument is the index n, an int.
      if (helper && i == 0) {
        std::ostringstream index;
        index << e.op(0);
        args += index.str();
      } else {
        args += emit(e.op(i)).s;
      }
    }
    if (fn == "nonnegative_part") return {"max(T(0), T(" + args + "))", Text::atom};  // not counted
    if (helper) {
      // The longest run of its loop (helper_costs.hpp).
      const OpCount cost = helper_costs::expression_helper(fn, GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_int());
      scopes_.back().generic += cost;
      scopes_.back().longest += cost;
      return {fn + "<T>(" + args + ")", Text::atom};
    }
    if (fn == "maximum") return {"max(T(" + emit(e.op(0)).s + "), T(" + emit(e.op(1)).s + "))", Text::atom};
    if (fn == "minimum") return {"min(T(" + emit(e.op(0)).s + "), T(" + emit(e.op(1)).s + "))", Text::atom};
    if (fn == "atan2" || fn == "atan") count(&OpCount::atan);
    else if (fn == "log" || fn == "asinh") count(&OpCount::log);
    else count(&OpCount::other);
    return {fn + "(" + args + ")", Text::atom};
  }

  // x^e for a rational e with denominator 1 or 2, from memoised pieces.
  std::string power(const ex& base, const numeric& e) {
    if (e == 1) return named(base);
    const ex key = GiNaC::pow(base, e);
    if (const std::string* m = find_memo(key)) return *m;
    std::string text;
    if (is_half_integer(e)) {
      // x^(m/2) = (√x)^m: one sqrt serves every half-integer power of x.
      const numeric m = 2 * e;
      const std::string root = sqrt_of(base);
      if (m == 1) return root;
      if (m.is_negative()) {
        const ex root_expr = root_expression(base);
        return power_of_name(GiNaC::pow(root_expr, -1), reciprocal(root_expr), -m);
      }
      text = power(base, (m - 1) / 2) + " * " + root;  // x^k √x
      count(&OpCount::mul);
    } else if (!e.is_integer()) {
      throw std::logic_error("unsupported exponent");
    } else if (e.is_negative()) {
      const std::string r = reciprocal(base);
      if (e == -1) return r;
      return power_of_name(GiNaC::pow(base, -1), r, -e);
    } else if (auto sq = square_of(base); sq && e.is_even()) {
      return power(*sq, e / 2);  // (√Q)^(2k) = Q^k
    } else if (sq) {
      text = power(*sq, (e - 1) / 2) + " * " + named(base);  // (√Q)^(2k+1) = Q^k √Q
      count(&OpCount::mul);
    } else if (e == 2 && uses_[key] <= 1) {
      const std::string x = named(base);  // a lone square stays inline
      count(&OpCount::mul);
      return x + " * " + x;
    } else {
      return power_of_name(base, named(base), e);
    }
    const std::string name = new_temp(text, key);
    scopes_.back().memo[key] = name;
    return name;
  }

  // y^k (k ≥ 2) where y is already named; memoises y^j along the way.
  std::string power_of_name(const ex& y, const std::string& y_name, const numeric& k) {
    if (k == 1) return y_name;
    const ex key = GiNaC::pow(y, k);
    if (const std::string* m = find_memo(key)) return *m;
    std::string text;
    if (k.is_even()) {
      const std::string half = power_of_name(y, y_name, k / 2);
      text = half + " * " + half;
    } else {
      text = power_of_name(y, y_name, k - 1) + " * " + y_name;
    }
    count(&OpCount::mul);
    const std::string name = new_temp(text, key);
    scopes_.back().memo[key] = name;
    return name;
  }

  // The expression that names √base: a declared root symbol, or base^(1/2).
  ex root_expression(const ex& base) const {
    if (is_a<symbol>(base)) {
      auto it = program_.root_of_square_.find(GiNaC::ex_to<symbol>(base));
      if (it != program_.root_of_square_.end() && names_.count(it->second)) return it->second;
    }
    return GiNaC::pow(base, GiNaC::numeric(1, 2));
  }

  std::string sqrt_of(const ex& base) {
    const ex key = root_expression(base);
    if (is_a<symbol>(key)) return named(key);
    if (const std::string* m = find_memo(key)) return *m;
    const std::string name = new_temp("sqrt(" + emit(base).s + ")", key);
    count(&OpCount::sqrt);
    scopes_.back().memo[key] = name;
    return name;
  }

  std::string reciprocal(const ex& base) {
    const ex key = GiNaC::pow(base, -1);
    if (const std::string* m = find_memo(key)) return *m;
    std::string text;
    if (auto root = root_of(base)) {
      const std::string r = reciprocal(*root);  // 1/Q = (1/√Q)²: one division
      text = r + " * " + r;
      count(&OpCount::mul);
    } else {
      text = "T(1) / " + as_divisor(emit(base));
      count(&OpCount::div);
    }
    const std::string name = new_temp(text, key);
    scopes_.back().memo[key] = name;
    return name;
  }

  std::optional<symbol> square_of(const ex& e) const {
    if (!is_a<symbol>(e) || !names_.count(GiNaC::ex_to<symbol>(e))) return std::nullopt;
    auto it = program_.square_of_root_.find(GiNaC::ex_to<symbol>(e));
    if (it == program_.square_of_root_.end()) return std::nullopt;
    return it->second;
  }
  std::optional<symbol> root_of(const ex& e) const {
    if (!is_a<symbol>(e)) return std::nullopt;
    auto it = program_.root_of_square_.find(GiNaC::ex_to<symbol>(e));
    if (it == program_.root_of_square_.end() || !names_.count(it->second)) return std::nullopt;
    // Only worth it when the root's reciprocal is needed anyway.
    if (reciprocal_uses_.count(it->second) == 0) return std::nullopt;
    return it->second;
  }

  // ---- helper calls that fill an array
  void emit_array_call(const ArrayCall& call) {
    std::string args;
    for (const std::string& a : call.fixed_args) args += a + ", ";
    for (const ex& a : call.args) args += emit(a).s + ", ";
    std::string guard;
    for (const ex& c : call.guard) guard += (guard.empty() ? "" : " && ") + condition_text(c);
    const std::string statement = call.function + "(" + args + call.array + ".data());";
    const std::string declaration = "std::array<T, " + std::to_string(call.elements.size()) + "> " + call.array;
    if (guard.empty()) {
      line(declaration + ";");
      line(statement);
    } else {
      line(declaration + "{};  // 0 where the call is not made");
      line("if (" + guard + ") {");
      scopes_.emplace_back();  // for the indentation only: nothing is computed inside
      line(statement);
      scopes_.pop_back();
      line("}");
    }
    scopes_.back().generic += call.ops;
    scopes_.back().longest += call.ops;
    for (size_t i = 0; i < call.elements.size(); ++i)
      names_[call.elements[i]] = call.array + "[" + std::to_string(i) + "]";
  }

  // ---- run-time choice between forms

  // The C++ test of a condition c ≥ 0. Where c is ±y + m for a number m,
  // the test compares y with the constant (y ≥ −m, y ≤ m) instead of
  // computing c: no subtraction, and the same outcome for every y,
  // NaN included, since rounding is monotonic and keeps the sign of y − m.
  std::string condition_text(const ex& c) {
    ex rest = c;
    numeric offset = 0;
    if (is_a<GiNaC::add>(c)) {
      for (size_t i = 0; i < c.nops(); ++i)
        if (is_a<numeric>(c.op(i))) offset = GiNaC::ex_to<numeric>(c.op(i));
      rest = c - offset;
    }
    bool negated = false;
    if (is_a<GiNaC::mul>(rest) && rest.nops() == 2 && rest.op(1).is_equal(-1)) {
      negated = true;
      rest = rest.op(0);
    }
    if (offset.is_zero() && !negated) return named(c) + " >= T(0)";
    return named(rest) + (negated ? " <= " : " >= ") + constant(negated ? offset : -offset).s;
  }

  void emit_choice(const Choice& choice) {
    for (const symbol& t : choice.targets) line("T " + t.get_name() + ";");
    // Conditions are computed up front, so no branch hides another's temporaries.
    std::vector<std::string> conditions;
    for (size_t i = 0; i + 1 < choice.alternatives.size(); ++i) {
      std::string all;
      for (const ex& c : choice.alternatives[i].conditions)
        all += (all.empty() ? "" : " && ") + condition_text(c);
      conditions.push_back(all);
    }
    // In generic_only mode an alternative that calls a helper with a loop of
    // run-time length (no fixed OpCount) is left out: the function then
    // reports, through generic_applies, where the full program takes it.
    auto has_variable_loop = [](const Alternative& a) {
      if (std::any_of(a.calls.begin(), a.calls.end(), [](const ArrayCall& c) { return !c.fixed_rule; })) return true;
      for (const auto& [s, v] : a.steps)
        if (calls_loop_helper(v)) return true;
      return std::any_of(a.values.begin(), a.values.end(), calls_loop_helper);
    };
    std::vector<size_t> kept;
    for (size_t i = 0; i < choice.alternatives.size(); ++i) {
      const bool skip = forms_ == Forms::generic_only && has_variable_loop(choice.alternatives[i]);
      if (skip && i + 1 == choice.alternatives.size())
        throw std::logic_error("generic_only: the fallback form calls a loop helper");
      if (skip) {
        // Taken by the full program where its conditions hold and no kept
        // earlier alternative's do.
        std::string taken = "(" + conditions[i] + ")";
        for (size_t j : kept) taken += " && !(" + conditions[j] + ")";
        special_forms_ += (special_forms_.empty() ? "(" : " || (") + taken + ")";
      } else {
        kept.push_back(i);
      }
    }
    // An if / else-if / else chain over the kept alternatives.
    OpCount longest, generic;
    for (size_t k = 0; k < kept.size(); ++k) {
      const size_t i = kept[k];
      const bool last = k + 1 == kept.size();
      std::string opening;
      if (!last) {
        opening = std::string(k == 0 ? "if (" : "} else if (") + conditions[i] + ") {";
      } else if (k > 0) {
        opening = "} else {";
      } else {
        opening = "{";  // a single form: its temporaries stay local all the same
      }
      const Scope branch = emit_alternative(choice, i, opening);
      if (branch.longest.total() > longest.total()) longest = branch.longest;
      if (i == choice.generic) generic = branch.generic;
    }
    line("}");
    scopes_.back().generic += generic;
    scopes_.back().longest += longest;
    for (const symbol& t : choice.targets) names_[t] = t.get_name();
  }

  // One alternative of a choice, in its own scope; returns that scope.
  Scope emit_alternative(const Choice& choice, size_t i, const std::string& opening) {
    const Alternative& alt = choice.alternatives[i];
    line(opening);
    scopes_.emplace_back();
    line("// " + alt.why);
    for (const auto& [s, v] : alt.steps) define(s, v);
    for (const ArrayCall& call : alt.calls) emit_array_call(call);
    if (alt.refinement)
      emit_refinement(choice.targets, alt);
    else
      assign(choice.targets, alt.values);
    Scope branch = std::move(scopes_.back());
    scopes_.pop_back();
    return branch;
  }

  void assign(const std::vector<symbol>& targets, const std::vector<ex>& values) {
    for (size_t j = 0; j < targets.size(); ++j) line(targets[j].get_name() + " = " + emit(values[j]).s + ";");
  }

  // The targets whose value the refinement keeps, assigned first; then
  // if (refinement's conditions) { its values } else { the alternative's
  // values } for the others, each in its own scope. The generic path takes
  // the latter.
  void emit_refinement(const std::vector<symbol>& all_targets, const Alternative& alt) {
    std::vector<symbol> targets;
    std::vector<ex> refined_values, plain_values;
    for (size_t j = 0; j < all_targets.size(); ++j) {
      if (alt.values[j].is_equal(alt.refinement->values[j])) {
        assign({all_targets[j]}, {alt.values[j]});
      } else {
        targets.push_back(all_targets[j]);
        refined_values.push_back(alt.refinement->values[j]);
        plain_values.push_back(alt.values[j]);
      }
    }
    std::string all;
    for (const ex& c : alt.refinement->conditions) all += (all.empty() ? "" : " && ") + condition_text(c);
    auto branch = [&](const std::string& opening, const std::string& why, const std::vector<ex>& values) {
      line(opening);
      scopes_.emplace_back();
      if (!why.empty()) line("// " + why);
      assign(targets, values);
      Scope s = std::move(scopes_.back());
      scopes_.pop_back();
      return s;
    };
    const Scope refined = branch("if (" + all + ") {", alt.refinement->why, refined_values);
    const Scope plain = branch("} else {", "", plain_values);
    line("}");
    scopes_.back().generic += plain.generic;
    scopes_.back().longest += refined.longest.total() > plain.longest.total() ? refined.longest : plain.longest;
  }

  const StraightLineProgram& program_;
  Forms forms_;
  std::string special_forms_;  // generic_only: where a non-generic form is due
  std::ostringstream body_;
  std::vector<Scope> scopes_;
  std::map<ex, int, ex_is_less> uses_;
  std::map<ex, int, ex_is_less> reciprocal_uses_;
  std::map<symbol, std::string, ex_is_less> names_;
  std::set<symbol, ex_is_less> input_symbols_;
  std::set<std::string> inputs_read_;  // C++ text of the inputs the code reads
  std::vector<bool> live_;
  std::map<size_t, Choice> live_choices_;  // by step: the choice with its live targets only
  std::string pending_name_;
  ex pending_value_;
  int next_temp_ = 0;
};

EmittedCode StraightLineProgram::emit(Forms forms) const { return Emitter(*this, forms).run(); }

// ---- PreparedQuantities

namespace {

std::string printed(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

struct MapWith : GiNaC::map_function {
  explicit MapWith(std::function<ex(const ex&)> f) : f_(std::move(f)) {}
  ex operator()(const ex& e) override { return f_(e); }
  std::function<ex(const ex&)> f_;
};

}  // namespace

ex PreparedQuantities::canonical(const ex& e) const {
  std::set<symbol, ex_is_less> symbols;
  collect_symbols(e, symbols);
  GiNaC::exmap map;
  for (const symbol& s : symbols) {
    const symbol& c = canonical_.at(s.get_name());
    if (!c.is_equal(s)) map[s] = c;
  }
  return map.empty() ? e : e.subs(map);
}

std::string PreparedQuantities::field_for(const ex& value, const std::string& name) {
  const std::string key = printed(value);
  if (auto it = field_by_key_.find(key); it != field_by_key_.end()) return fields_[it->second].name;
  field_by_key_[key] = fields_.size();
  fields_.push_back({name, value});
  return name;
}

StraightLineProgram PreparedQuantities::per_point_part(const StraightLineProgram& program,
                                                       const std::function<std::string(const std::string&)>& rename) {
  StraightLineProgram out;
  std::set<symbol, ex_is_less> per_primitive;  // this program's symbols that depend on the primitive only
  std::map<std::string, symbol> local;          // field name → the symbol `out` reads it as

  auto only_per_primitive = [&](const ex& e) {  // true for a constant too
    std::set<symbol, ex_is_less> symbols;
    collect_symbols(e, symbols);
    return std::all_of(symbols.begin(), symbols.end(), [&](const symbol& s) { return per_primitive.count(s) > 0; });
  };
  auto is_constant = [](const ex& e) { return is_a<numeric>(e); };
  auto register_step = [&](const symbol& s, const ex& value) {
    per_primitive.insert(s);
    const ex c = canonical(value);
    if (defined_.count(s.get_name())) {
      const auto same = std::find_if(steps_.begin(), steps_.end(),
                                     [&](const auto& step) { return step.first.get_name() == s.get_name(); });
      if (same == steps_.end() || printed(same->second) != printed(c))
        throw std::logic_error("prepared quantity " + s.get_name() + " differs between the kernel's programs");
      return;
    }
    canonical_.emplace(s.get_name(), s);
    defined_.insert(s.get_name());
    steps_.emplace_back(canonical_.at(s.get_name()), c);
  };
  // The symbol `out` reads the per-primitive expression e as.
  auto hoist = [&](const ex& e) -> ex {
    const bool plain = is_a<symbol>(e);
    const std::string name =
        field_for(canonical(e), plain ? GiNaC::ex_to<symbol>(e).get_name() : "seg" + std::to_string(seg_count_));
    if (!plain && name == "seg" + std::to_string(seg_count_)) ++seg_count_;
    if (auto it = local.find(name); it != local.end()) return it->second;
    const symbol s = plain ? GiNaC::ex_to<symbol>(e) : symbol(name);
    out.add_input(s, name);
    local.emplace(name, s);
    return s;
  };
  // e with every per-primitive part replaced by a field: a whole
  // sub-expression, or the per-primitive terms of a sum grouped into one.
  std::function<ex(const ex&)> transform = [&](const ex& e) -> ex {
    if (is_constant(e)) return e;
    if (only_per_primitive(e)) return hoist(e);
    if (is_a<symbol>(e)) return e;
    const bool sum = is_a<GiNaC::add>(e);
    if (sum || is_a<GiNaC::mul>(e)) {
      numeric constant = sum ? 0 : 1;
      std::vector<ex> group;
      ex rest = sum ? ex(0) : ex(1);
      for (size_t i = 0; i < e.nops(); ++i) {
        const ex& op = e.op(i);
        if (is_constant(op))
          constant = sum ? constant + GiNaC::ex_to<numeric>(op) : constant * GiNaC::ex_to<numeric>(op);
        else if (only_per_primitive(op))
          group.push_back(op);
        else
          rest = sum ? rest + transform(op) : rest * transform(op);
      }
      if (!sum) {
        // Mixed products keep their factors: regrouping them moves the
        // roundings of the recurrences (measured on the verifier's sweep:
        // up to 2.6× the baseline's error in two cells), for one product saved.
        for (const ex& factor : group) rest *= hoist(factor);
        return rest * constant;
      }
      // A lone term ±x (x a symbol) costs nothing more than x.
      if (group.size() == 1 && constant.is_zero()) {
        const ex& term = group[0];
        if (is_a<symbol>(term)) return rest + hoist(term);
        if (is_a<GiNaC::mul>(term) && term.nops() == 2 && is_a<symbol>(term.op(0)) && term.op(1).is_equal(-1))
          return rest - hoist(term.op(0));
      }
      if (group.empty()) return rest + constant;
      ex grouped = constant;
      for (const ex& term : group) grouped += term;
      return rest + hoist(grouped);
    }
    if (is_a<GiNaC::power>(e)) return GiNaC::pow(transform(e.op(0)), e.op(1));
    if (is_a<GiNaC::function>(e)) {
      MapWith map(transform);
      return e.map(map);
    }
    throw std::logic_error("per_point_part: cannot split " + printed(e));
  };

  for (const auto& [s, cpp] : program.inputs_) {
    if (per_primitive_input_(cpp)) {
      per_primitive.insert(s);
      if (!canonical_.count(s.get_name())) {
        canonical_.emplace(s.get_name(), s);
        inputs_.emplace_back(s, cpp);
        defined_.insert(s.get_name());
      }
    } else {
      out.add_input(s, rename(cpp));
    }
  }
  for (const StraightLineProgram::Step& step : program.steps_) {
    if (step.kind == StraightLineProgram::Step::Kind::define) {
      const symbol& target = step.targets[0];
      if (only_per_primitive(step.value))
        register_step(target, step.value);
      else
        out.define(target, transform(step.value));
      continue;
    }
    Choice choice = step.choice;
    for (Alternative& alt : choice.alternatives) {
      for (ex& c : alt.conditions) c = transform(c);
      std::vector<std::pair<symbol, ex>> steps;
      for (const auto& [s, v] : alt.steps) {
        if (only_per_primitive(v))
          register_step(s, v);
        else
          steps.emplace_back(s, transform(v));
      }
      alt.steps = std::move(steps);
      for (ArrayCall& call : alt.calls) {
        for (ex& c : call.guard) c = transform(c);
        for (ex& a : call.args) a = transform(a);
      }
      for (ex& v : alt.values) v = transform(v);
      if (alt.refinement) {
        for (ex& c : alt.refinement->conditions) c = transform(c);
        for (ex& v : alt.refinement->values) v = transform(v);
      }
    }
    out.choose(std::move(choice));
  }
  for (const auto& [lhs, value] : program.outputs_) out.add_output(lhs, transform(value));
  for (const auto& [square, root] : program.root_of_square_) {
    if (per_primitive.count(square) && per_primitive.count(root))
      root_of_square_.emplace(canonical_.at(square.get_name()), canonical_.at(root.get_name()));
    else if (!per_primitive.count(square) && !per_primitive.count(root))
      out.declare_square_root(root, square);
  }
  return out;
}

std::string PreparedQuantities::read_fields_text(const std::set<std::string>& read) const {
  std::string text;
  for (std::size_t i = 0; i < fields_.size(); ++i)
    if (read.count(fields_[i].name)) text += "  const T " + fields_[i].name + " = pre[" + std::to_string(i) + "];\n";
  return text;
}

StraightLineProgram PreparedQuantities::prepare_program(const std::set<std::string>* only) const {
  StraightLineProgram p;
  for (const auto& [s, cpp] : inputs_) p.add_input(s, cpp);
  for (const auto& [s, value] : steps_) p.define(s, value);
  for (const auto& [square, root] : root_of_square_) p.declare_square_root(root, square);
  for (std::size_t i = 0; i < fields_.size(); ++i)
    if (!only || only->count(fields_[i].name)) p.add_output("pre[" + std::to_string(i) + "]", fields_[i].value);
  return p;
}

}  // namespace skelconv::codegen
