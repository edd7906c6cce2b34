#include <glissade/contact/discretisation/mortar_variables.h>

#include <algorithm>
#include <cmath>

namespace glissade::mortar
{
  void
  merge_entries(DofVector &v)
  {
    std::sort(v.begin(),
              v.end(),
              [](const DofCoefficient &a, const DofCoefficient &b) {
                return std::make_pair(a.body, a.dof) <
                       std::make_pair(b.body, b.dof);
              });
    DofVector merged;
    for (const auto &e : v)
      if (!merged.empty() && merged.back().body == e.body &&
          merged.back().dof == e.dof)
        merged.back().value += e.value;
      else
        merged.push_back(e);
    v = std::move(merged);
  }

  double
  root_near_linear(const double A, const double B, const double C)
  {
    double s = -C / B;
    for (unsigned int it = 0; it < 20 && std::isfinite(s); ++it)
      {
        const double step = (A * s * s + B * s + C) / (2. * A * s + B);
        s -= step;
        if (std::abs(step) < 1e-15)
          break;
      }
    return s;
  }

  void
  merge_proportional_terms(std::vector<ContactLinearization::Term> &terms)
  {
    std::vector<ContactLinearization::Term> merged;
    for (auto &term : terms)
      {
        merge_entries(term.row);
        if (term.row.empty() || term.load.empty())
          continue;
        const auto largest_entry = [](const DofVector &row) {
          return std::max_element(row.begin(),
                                  row.end(),
                                  [](const auto &a, const auto &b) {
                                    return std::abs(a.value) <
                                           std::abs(b.value);
                                  }) -
                 row.begin();
        };
        const auto   i      = largest_entry(term.row);
        const double top    = std::abs(term.row[i].value);
        bool         joined = false;
        for (auto &kept : merged)
          {
            if (kept.row.size() != term.row.size() ||
                kept.row[i].body != term.row[i].body ||
                kept.row[i].dof != term.row[i].dof || kept.row[i].value == 0.)
              continue;
            const double ratio        = term.row[i].value / kept.row[i].value;
            bool         proportional = true;
            for (std::size_t k = 0; proportional && k < term.row.size(); ++k)
              proportional = kept.row[k].body == term.row[k].body &&
                             kept.row[k].dof == term.row[k].dof &&
                             std::abs(term.row[k].value -
                                      ratio * kept.row[k].value) <= 1e-12 * top;
            if (!proportional)
              continue;
            // The larger row stays, so that no load is scaled up: a
            // Hermite end whose reference tangent lies along an axis has
            // a row of round-off beside its other component's.
            if (std::abs(ratio) <= 1.)
              for (const auto &e : term.load)
                kept.load.push_back({e.body, e.dof, ratio * e.value});
            else
              {
                for (auto &e : kept.load)
                  e.value /= ratio;
                kept.load.insert(kept.load.end(),
                                 term.load.begin(),
                                 term.load.end());
                kept.row = std::move(term.row);
              }
            joined = true;
            break;
          }
        if (!joined)
          merged.push_back(std::move(term));
      }
    for (auto &term : merged)
      merge_entries(term.load);
    terms = std::move(merged);
  }

  void
  add_scaled(DofVector &out, const double c, const DofVector &a)
  {
    if (c != 0.)
      for (const auto &e : a)
        out.push_back({e.body, e.dof, c * e.value});
  }
} // namespace glissade::mortar
