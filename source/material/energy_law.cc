// A hyperelastic law given by its strain energy alone, its stress and
// tangent by automatic differentiation (include/glissade/material/
// energy_law.h); and `Law = energy`, whose energy is a formula of the .prm.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <glissade/base/input_error.h>
#include <glissade/material/energy_expression.h>
#include <glissade/material/energy_law.h>

#include <any>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** The components of a symmetric tensor, in the order of the six
     *  independent variables. */
    constexpr unsigned int component_row[6] = {0, 1, 2, 0, 0, 1};
    constexpr unsigned int component_col[6] = {0, 1, 2, 1, 2, 2};

    using InnerNumber = Sacado::Fad::SFad<double, 6>;

    /** log(1 + x) with its derivatives (Sacado has no log1p): ln J of a
     *  strain of 1e-8 keeps its digits, as in the hand-written laws. */
    InnerNumber
    log1p_of(const InnerNumber &x)
    {
      InnerNumber  result(x);
      const double factor = 1. / (1. + x.val());
      result.val()        = std::log1p(x.val());
      for (int i = 0; i < 6; ++i)
        result.fastAccessDx(i) = x.fastAccessDx(i) * factor;
      return result;
    }

    EnergyNumber
    log1p_of(const EnergyNumber &x)
    {
      EnergyNumber      result(x);
      const InnerNumber factor = 1. / (1. + x.val());
      result.val()             = log1p_of(x.val());
      for (int i = 0; i < 6; ++i)
        result.fastAccessDx(i) = x.fastAccessDx(i) * factor;
      return result;
    }

    class EnergyLaw : public HyperelasticLaw
    {
    public:
      EnergyLaw(const std::string &name, StrainEnergy energy)
        : law_name(name)
        , energy_function(std::move(energy))
      {}

      void
      evaluate(const SymmetricTensor<2, 3> &E,
               SymmetricTensor<2, 3>       &S,
               SymmetricTensor<4, 3>       &D) const override
      {
        const EnergyNumber W = energy_at(E);
        // The six variables are E_11, E_22, E_33 and the shared E_12 =
        // E_21, E_13, E_23: dW/dE_12 = (dW/de_3) / 2, and so for each
        // off-diagonal index of the tangent.
        for (unsigned int a = 0; a < 6; ++a)
          {
            const double fa                       = a < 3 ? 1. : 0.5;
            S[component_row[a]][component_col[a]] = fa * W.dx(a).val();
            for (unsigned int b = 0; b < 6; ++b)
              {
                const double fb = b < 3 ? 1. : 0.5;
                D[component_row[a]][component_col[a]][component_row[b]]
                 [component_col[b]] = fa * fb * W.dx(a).dx(b);
              }
          }
      }

      double
      energy(const SymmetricTensor<2, 3> &E) const override
      {
        return energy_at(E).val().val();
      }

      std::string
      name() const override
      {
        return law_name;
      }

    private:
      EnergyNumber
      energy_at(const SymmetricTensor<2, 3> &E) const
      {
        std::array<EnergyNumber, 6> e;
        for (unsigned int a = 0; a < 6; ++a)
          e[a] = EnergyNumber(
            6, a, InnerNumber(6, a, E[component_row[a]][component_col[a]]));
        // A = 2 E = C - I, and the invariants of C = I + A from A's:
        // I1 = 3 + tr A, I2 = 3 + 2 tr A + ((tr A)^2 - A:A) / 2, det C =
        // 1 + tr A + ((tr A)^2 - A:A) / 2 + det A, with no difference of
        // numbers near 1 (ln J by log1p).
        std::array<EnergyNumber, 6> A;
        for (unsigned int a = 0; a < 6; ++a)
          A[a] = 2. * e[a];
        const EnergyNumber tr_A = A[0] + A[1] + A[2];
        const EnergyNumber A_A  = A[0] * A[0] + A[1] * A[1] + A[2] * A[2] +
                                 2. * (A[3] * A[3] + A[4] * A[4] + A[5] * A[5]);
        const EnergyNumber det_A = A[0] * (A[1] * A[2] - A[5] * A[5]) -
                                   A[3] * (A[3] * A[2] - A[5] * A[4]) +
                                   A[4] * (A[3] * A[5] - A[1] * A[4]);
        const EnergyNumber second = 0.5 * (tr_A * tr_A - A_A);
        StrainMeasures     s;
        s.I1   = 3. + tr_A;
        s.I2   = 3. + 2. * tr_A + second;
        s.I3   = 1. + tr_A + second + det_A;
        s.ln_J = 0.5 * log1p_of(EnergyNumber(tr_A + second + det_A));
        s.J    = exp(s.ln_J);
        for (unsigned int a = 0; a < 6; ++a)
          s.C[a] = (a < 3 ? 1. : 0.) + A[a];
        return energy_function(s);
      }

      const std::string  law_name;
      const StrainEnergy energy_function;
    };



    /** What `Law = energy` reads: its formula and constants, and where. */
    struct EnergyFormula
    {
      std::string                   text;
      std::map<std::string, double> constants;
      std::string                   where;
    };

    /** Law = energy's formula unless the .prm gives one: the neo-Hookean
     *  energy. */
    const std::string default_formula =
      "mu / 2 * (I1 - 3) - mu * lnJ + lambda / 2 * lnJ^2";

    const std::vector<std::string> formula_variables =
      {"I1", "I2", "I3", "J", "lnJ", "C11", "C22", "C33", "C12", "C13", "C23"};

    /** The formula as a StrainEnergy, with lambda and mu among its
     *  constants. */
    StrainEnergy
    energy_of_formula(const EnergyFormula &formula,
                      const double         lambda,
                      const double         mu)
    {
      std::map<std::string, double> constants = formula.constants;
      constants["lambda"]                     = lambda;
      constants["mu"]                         = mu;
      const auto expression =
        std::make_shared<EnergyExpression>(formula.text,
                                           formula_variables,
                                           constants);
      return [expression](const StrainMeasures &s) {
        const EnergyNumber values[] = {s.I1,
                                       s.I2,
                                       s.I3,
                                       s.J,
                                       s.ln_J,
                                       s.C[0],
                                       s.C[1],
                                       s.C[2],
                                       s.C[3],
                                       s.C[4],
                                       s.C[5]};
        return expression->evaluate(values);
      };
    }
  } // namespace



  std::unique_ptr<HyperelasticLaw>
  make_energy_law(const std::string &name, StrainEnergy energy)
  {
    return std::make_unique<EnergyLaw>(name, std::move(energy));
  }



  void
  declare_energy_law_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Strain energy",
      default_formula,
      Patterns::Anything(),
      "Law = energy: the strain energy W per unit reference volume, a "
      "formula of I1, I2, I3 (the invariants of C = F^T F), J, lnJ, the "
      "components C11, C22, C33, C12, C13, C23, the Lame constants lambda "
      "and mu of Young modulus and Poisson ratio, and the Strain energy "
      "constants; + - * / ^, log, exp, sqrt, pow. The stress and tangent "
      "are its derivatives, by automatic differentiation. W must vanish in "
      "slope at C = I (no stress at rest); its second derivative there is "
      "the law at small strain. (The default is the neo-Hookean law.)");
    prm.declare_entry("Strain energy constants",
                      "",
                      Patterns::Anything(),
                      "Law = energy: named constants of the formula, as "
                      "'c1 = 0.4, c2 = 0.1'.");
  }



  std::any
  parse_energy_law_parameters(const ParameterHandler &prm,
                              const std::string      &where)
  {
    EnergyFormula formula;
    formula.text  = prm.get("Strain energy");
    formula.where = where;
    for (const std::string &item :
         Utilities::split_string_list(prm.get("Strain energy constants")))
      {
        const auto parts = Utilities::split_string_list(item, '=');
        double     value = 0.;
        bool       valid = parts.size() == 2 && !parts[0].empty();
        if (valid)
          try
            {
              value = Utilities::string_to_double(parts[1]);
            }
          catch (...)
            {
              valid = false;
            }
        if (!valid)
          throw InputError(where + "/Strain energy constants",
                           "'" + item + "' is not 'name = value'");
        for (const std::string &taken : formula_variables)
          if (parts[0] == taken || parts[0] == "lambda" || parts[0] == "mu")
            throw InputError(where + "/Strain energy constants",
                             "'" + parts[0] +
                               "' is a variable of the formula already");
        formula.constants[parts[0]] = value;
      }
    try
      {
        // (the formula's names and grammar; lambda and mu are known at
        // the law's creation)
        energy_of_formula(formula, 1., 1.);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(where + "/Strain energy", e.what());
      }
    return formula;
  }



  std::unique_ptr<HyperelasticLaw>
  make_energy_formula_law(const double    lambda,
                          const double    mu,
                          const std::any &settings)
  {
    EnergyFormula formula;
    if (settings.has_value())
      formula = std::any_cast<EnergyFormula>(settings);
    else
      formula.text = default_formula;
    auto law =
      make_energy_law("energy", energy_of_formula(formula, lambda, mu));
    // A stress at rest would move an unloaded body; a stress or tangent
    // that is not finite there is a formula undefined at C = I.
    SymmetricTensor<2, 3> S;
    SymmetricTensor<4, 3> D;
    law->evaluate(SymmetricTensor<2, 3>(), S, D);
    const std::string entry =
      (formula.where.empty() ? "Material" : formula.where) + "/Strain energy";
    if (!std::isfinite(S.norm()) || !std::isfinite(D.norm()))
      throw InputError(entry,
                       "the stress or tangent of '" + formula.text +
                         "' is not finite at rest (C = I)");
    if (S.norm() > 1e-10 * D.norm())
      throw InputError(entry,
                       "'" + formula.text + "' has a stress at rest (|S| = " +
                         std::to_string(S.norm()) +
                         " at C = I): its slope must vanish there");
    return law;
  }
} // namespace glissade
