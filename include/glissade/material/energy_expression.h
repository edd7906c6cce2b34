#pragma once

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * A formula of named variables, parsed once and evaluated on any number
   * type: doubles, or the automatic-differentiation numbers of a law given
   * by its strain energy (EnergyLaw), which is why it is not muParser (its
   * evaluation is doubles only, and a stress and tangent by finite
   * differences would not reach a hand-written law's digits).
   *
   * The grammar is what a strain energy needs: numbers,
   * variables, + - * / ^ (right associative, above the unary minus, as in
   * -x^2 = -(x^2)), parentheses, and the functions log, exp, sqrt and
   * pow(a, b). A constant exponent is applied as such, integer ones by
   * products (so that (ln J)^2 has a derivative where ln J < 0).
   */
  class EnergyExpression
  {
  public:
    /**
     * Parses `text` over the variables `variables` (their order is that of
     * the values evaluate() takes) and the named constants `constants`.
     * Throws std::invalid_argument with what is wrong and where.
     */
    EnergyExpression(const std::string                   &text,
                     const std::vector<std::string>      &variables,
                     const std::map<std::string, double> &constants);

    /** The formula at the variables' values `values` (as many as the
     *  variables). */
    template <typename Number>
    Number
    evaluate(const Number *values) const
    {
      return evaluate_node(root, values);
    }

  private:
    enum class Kind
    {
      constant,
      variable,
      negate,
      add,
      subtract,
      multiply,
      divide,
      power,
      constant_power,
      log,
      exp,
      sqrt
    };

    struct Node
    {
      Kind         kind;
      double       value       = 0.; // constant, constant_power's exponent
      unsigned int variable    = 0;  // variable
      unsigned int operands[2] = {0, 0};
    };

    template <typename Number>
    Number
    evaluate_node(const unsigned int index, const Number *values) const
    {
      using std::exp;
      using std::log;
      using std::pow;
      using std::sqrt;
      const Node &node = nodes[index];
      const auto  a = [&]() { return evaluate_node(node.operands[0], values); };
      const auto  b = [&]() { return evaluate_node(node.operands[1], values); };
      switch (node.kind)
        {
          case Kind::constant:
            return Number(node.value);
          case Kind::variable:
            return values[node.variable];
          case Kind::negate:
            return -a();
          case Kind::add:
            return a() + b();
          case Kind::subtract:
            return a() - b();
          case Kind::multiply:
            return a() * b();
          case Kind::divide:
            return a() / b();
          case Kind::power:
            return pow(a(), b());
          case Kind::constant_power:
            {
              const double p = node.value;
              if (p == std::round(p) && std::abs(p) <= 8.)
                {
                  const Number base   = a();
                  Number       result = Number(1.);
                  for (int k = 0; k < std::abs(static_cast<int>(p)); ++k)
                    result = result * base;
                  return p < 0. ? Number(1.) / result : result;
                }
              return pow(a(), p);
            }
          case Kind::log:
            return log(a());
          case Kind::exp:
            return exp(a());
          case Kind::sqrt:
            return sqrt(a());
        }
      return Number(0.);
    }

    class Parser;

    std::vector<Node> nodes;
    unsigned int      root = 0;
  };
} // namespace glissade
