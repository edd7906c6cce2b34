// A formula of named variables for any number type: the parser
// (include/glissade/material/energy_expression.h).

#include <glissade/material/energy_expression.h>

#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace glissade
{
  /**
   * Recursive descent over the text, one node per operation; each method
   * returns its node's index.
   *   sum     := product (('+' | '-') product)*
   *   product := unary (('*' | '/') unary)*
   *   unary   := ('-' | '+') unary | power
   *   power   := primary ('^' unary)?
   *   primary := number | name | name '(' sum (',' sum)? ')' | '(' sum ')'
   */
  class EnergyExpression::Parser
  {
  public:
    Parser(EnergyExpression                    &expression,
           const std::string                   &text,
           const std::vector<std::string>      &variables,
           const std::map<std::string, double> &constants)
      : expression(expression)
      , text(text)
      , variables(variables)
      , constants(constants)
    {}

    unsigned int
    parse()
    {
      const unsigned int root = sum();
      skip_spaces();
      if (position < text.size())
        fail("unexpected '" + std::string(1, text[position]) + "'");
      return root;
    }

  private:
    [[noreturn]] void
    fail(const std::string &what) const
    {
      throw std::invalid_argument(what + " at character " +
                                  std::to_string(position + 1) + " of '" +
                                  text + "'");
    }

    void
    skip_spaces()
    {
      while (position < text.size() &&
             std::isspace(static_cast<unsigned char>(text[position])))
        ++position;
    }

    bool
    accept(const char c)
    {
      skip_spaces();
      if (position < text.size() && text[position] == c)
        {
          ++position;
          return true;
        }
      return false;
    }

    unsigned int
    add(const Kind         kind,
        const unsigned int a     = 0,
        const unsigned int b     = 0,
        const double       value = 0.)
    {
      Node node;
      node.kind        = kind;
      node.operands[0] = a;
      node.operands[1] = b;
      node.value       = value;
      expression.nodes.push_back(node);
      return expression.nodes.size() - 1;
    }

    /** Whether a node's value depends on no variable. */
    bool
    is_constant(const unsigned int index) const
    {
      const Node &node = expression.nodes[index];
      switch (node.kind)
        {
          case Kind::constant:
            return true;
          case Kind::variable:
            return false;
          case Kind::negate:
          case Kind::log:
          case Kind::exp:
          case Kind::sqrt:
          case Kind::constant_power:
            return is_constant(node.operands[0]);
          default:
            return is_constant(node.operands[0]) &&
                   is_constant(node.operands[1]);
        }
    }

    unsigned int
    sum()
    {
      unsigned int left = product();
      while (true)
        if (accept('+'))
          left = add(Kind::add, left, product());
        else if (accept('-'))
          left = add(Kind::subtract, left, product());
        else
          return left;
    }

    unsigned int
    product()
    {
      unsigned int left = unary();
      while (true)
        if (accept('*'))
          left = add(Kind::multiply, left, unary());
        else if (accept('/'))
          left = add(Kind::divide, left, unary());
        else
          return left;
    }

    unsigned int
    unary()
    {
      if (accept('-'))
        return add(Kind::negate, unary());
      if (accept('+'))
        return unary();
      return power();
    }

    unsigned int
    power()
    {
      const unsigned int base = primary();
      if (!accept('^'))
        return base;
      const unsigned int exponent = unary();
      return power_node(base, exponent);
    }

    unsigned int
    power_node(const unsigned int base, const unsigned int exponent)
    {
      if (is_constant(exponent))
        {
          const double p = expression.evaluate_node<double>(exponent, nullptr);
          return add(Kind::constant_power, base, 0, p);
        }
      return add(Kind::power, base, exponent);
    }

    unsigned int
    primary()
    {
      skip_spaces();
      if (position >= text.size())
        fail("the formula ends where a value was expected");
      const char c = text[position];
      if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
          const char  *start = text.c_str() + position;
          char        *end   = nullptr;
          const double value = std::strtod(start, &end);
          if (end == start)
            fail("a number was expected");
          position += end - start;
          return add(Kind::constant, 0, 0, value);
        }
      if (accept('('))
        {
          const unsigned int inside = sum();
          if (!accept(')'))
            fail("')' expected");
          return inside;
        }
      if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_'))
        fail("unexpected '" + std::string(1, c) + "'");
      std::string name;
      while (position < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[position])) ||
              text[position] == '_'))
        name += text[position++];
      if (accept('('))
        return function(name);
      for (unsigned int k = 0; k < variables.size(); ++k)
        if (variables[k] == name)
          {
            const unsigned int index         = add(Kind::variable);
            expression.nodes[index].variable = k;
            return index;
          }
      const auto constant = constants.find(name);
      if (constant != constants.end())
        return add(Kind::constant, 0, 0, constant->second);
      std::string known;
      for (const auto &v : variables)
        known += (known.empty() ? "" : ", ") + v;
      for (const auto &[k, value] : constants)
        known += ", " + k;
      fail("unknown name '" + name + "' (known: " + known + ")");
    }

    unsigned int
    function(const std::string &name)
    {
      const unsigned int argument = sum();
      if (name == "pow")
        {
          if (!accept(','))
            fail("pow takes two arguments: pow(base, exponent)");
          const unsigned int exponent = sum();
          if (!accept(')'))
            fail("')' expected");
          return power_node(argument, exponent);
        }
      if (!accept(')'))
        fail("')' expected after the argument of " + name);
      if (name == "log" || name == "ln")
        return add(Kind::log, argument);
      if (name == "exp")
        return add(Kind::exp, argument);
      if (name == "sqrt")
        return add(Kind::sqrt, argument);
      fail("unknown function '" + name + "' (known: log, exp, sqrt, pow)");
    }

    EnergyExpression                    &expression;
    const std::string                   &text;
    const std::vector<std::string>      &variables;
    const std::map<std::string, double> &constants;
    std::size_t                          position = 0;
  };



  EnergyExpression::EnergyExpression(
    const std::string                   &text,
    const std::vector<std::string>      &variables,
    const std::map<std::string, double> &constants)
  {
    Parser parser(*this, text, variables, constants);
    root = parser.parse();
  }
} // namespace glissade
