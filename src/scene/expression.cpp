#include "scene/expression.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>

#include "core/types.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

namespace {
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
    p.DefineConst("pi", std::numbers::pi);
    p.DefineConst("e", std::numbers::e);
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
    else if (!constants.empty() && !token.empty()) {
      std::vector<std::string> names;
      for (const auto& c : constants) names.push_back(c.first);
      const std::string best = closest_word(e.GetToken(), names);
      if (!best.empty()) hint = "; did you mean '" + best + "'?";
    }
    throw InputError(where + ": invalid expression '" + text + "': " + e.GetMsg() + hint);
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
