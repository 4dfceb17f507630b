#pragma once
// A user expression in x, y, z and t (muparser), e.g. "1000*(1+1e-3*cos(2*pi*x/0.1))", plus
// named constants (the scene's `variables`, e.g. "speed*cos(angle*pi/180)").
#include <map>
#include <memory>
#include <string>

namespace monosph {

// Named constants an expression may use besides x, y, z, t, pi and e.
using Constants = std::map<std::string, double>;

// The expressions' function uniform(seed, stream): a number in [0, 1) that depends only on the
// two arguments, the same on every machine. Each is rounded to the nearest whole number (NaN
// when that is not finite or beyond +-2^53); with a = round(seed), b = round(stream) as 64-bit
// two's complement, u = splitmix64(splitmix64(a) + b) >> 11, times 2^-53.
double seeded_uniform(double seed, double stream);

// A number key written as an expression of the scene's variables, e.g.
// "2e-5*(uniform(seed,1)-0.5)" (no x, y, z or t). Throws InputError
// "<where>: expected a number, got '<text>' (...)" naming the reason; the value may be
// non-finite (the caller says so).
double constant_expression(const std::string& text, const std::string& where,
                           const Constants& constants);

class Expression {
 public:
  Expression();
  // Throws InputError "<where>: invalid expression '<text>': <reason>" (an unknown name near one
  // of the constants adds "did you mean '<constant>'?"). `variables`: which of x, y, z, t the
  // expression may use (a surface's velocity: "t" only).
  Expression(const std::string& text, const std::string& where, const Constants& constants = {},
             const std::string& variables = "xyzt");
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  ~Expression();

  // Not thread-safe: evaluate from one thread.
  double operator()(double x, double y = 0, double z = 0, double t = 0) const;
  bool empty() const { return !impl_; }
  bool depends_on_time() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace monosph
