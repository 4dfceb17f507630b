#include "scene/expression.hpp"

#include <muParser.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "core/types.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

namespace {
std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// What every expression knows besides its variables: pi, e and uniform(seed, stream).
void define_common(mu::Parser& p) {
  p.DefineConst("pi", std::numbers::pi);
  p.DefineConst("e", std::numbers::e);
  p.DefineFun("uniform", seeded_uniform);
}

// "did you mean '<constant>'?" for an unknown name near one of the constants, or "".
std::string constant_hint(const std::string& token, const Constants& constants) {
  if (constants.empty() || token.empty() ||
      !(std::isalpha(static_cast<unsigned char>(token[0])) || token[0] == '_'))
    return "";  // not a name (a parenthesis, an operator)
  std::vector<std::string> names;
  for (const auto& c : constants) names.push_back(c.first);
  const std::string best = closest_word(token, names);
  return best.empty() ? "" : "did you mean '" + best + "'?";
}

std::string variables_text(const std::string& v) {
  std::string s;
  for (std::size_t k = 0; k < v.size(); ++k)
    s += std::string(k == 0 ? "" : k + 1 == v.size() ? " and " : ", ") + v[k];
  return s;
}
}  // namespace

struct Expression::Impl {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, t = 0;
  bool uses_t = false;
  std::string text;
};

Expression::Expression(const std::string& text, const std::string& where,
                       const Constants& constants, const std::string& variables)
    : impl_(std::make_unique<Impl>()) {
  auto& p = impl_->parser;
  impl_->text = text;
  try {
    define_common(p);
    double* slots[] = {&impl_->x, &impl_->y, &impl_->z, &impl_->t};
    for (int k = 0; k < 4; ++k)
      if (variables.find("xyzt"[k]) != std::string::npos)
        p.DefineVar(std::string(1, "xyzt"[k]), slots[k]);
    for (const auto& [name, value] : constants) p.DefineConst(name, value);
    p.SetExpr(text);
    p.Eval();  // forces parsing; reports syntax errors now
    impl_->uses_t = p.GetUsedVar().count("t") > 0;
  } catch (mu::Parser::exception_type& e) {
    std::string hint;
    const std::string token = e.GetToken();
    if (token.size() == 1 && std::string("xyzt").find(token) != std::string::npos)
      hint = "; this expression takes only " + variables_text(variables);
    else if (const std::string best = constant_hint(token, constants); !best.empty())
      hint = "; " + best;
    throw InputError(where + ": invalid expression '" + text + "': " + e.GetMsg() + hint);
  }
}

double seeded_uniform(double seed, double stream) {
  constexpr double kMax = 9007199254740992.0;  // 2^53: every whole number up to it is exact
  const double a = std::round(seed), b = std::round(stream);
  if (!(std::abs(a) <= kMax) || !(std::abs(b) <= kMax))
    return std::numeric_limits<double>::quiet_NaN();
  const auto ua = static_cast<std::uint64_t>(static_cast<std::int64_t>(a));
  const auto ub = static_cast<std::uint64_t>(static_cast<std::int64_t>(b));
  return static_cast<double>(splitmix64(splitmix64(ua) + ub) >> 11) * 0x1.0p-53;
}

double constant_expression(const std::string& text, const std::string& where,
                           const Constants& constants) {
  const std::string head = where + ": expected a number, got '" + text + "'";
  try {
    mu::Parser p;
    define_common(p);
    for (const auto& [name, value] : constants) p.DefineConst(name, value);
    p.SetExpr(text);
    const double v = p.Eval();
    if (p.GetNumResults() != 1) throw InputError(head + " (a list of values, not one)");
    return v;
  } catch (mu::Parser::exception_type& e) {
    const std::string token = e.GetToken();
    std::string hint = token.size() == 1 && std::string("xyzt").find(token) != std::string::npos
                           ? "x, y, z and t have no value in a number key"
                           : constant_hint(token, constants);
    // The whole value one unknown word ('fine'): a misspelt number or variable, not an expression.
    if (token != text)
      hint = "as an expression of the scene's variables: " + e.GetMsg() +
             (hint.empty() ? "" : "; " + hint);
    throw InputError(head + (hint.empty() ? "" : " (" + hint + ")"));
  }
}

Expression::Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

double Expression::operator()(double x, double y, double z, double t) const {
  impl_->x = x;
  impl_->y = y;
  impl_->z = z;
  impl_->t = t;
  return impl_->parser.Eval();
}

bool Expression::depends_on_time() const {
  return impl_ && impl_->uses_t;
}

}  // namespace monosph
