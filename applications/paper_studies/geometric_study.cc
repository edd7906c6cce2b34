#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/contact/curves/bspline_curve.h>
#include <glissade/contact/curves/faceted_curve.h>
#include <glissade/contact/curves/hermite_curve.h>
#include <glissade/contact/curves/lagrange_edge_curve.h>
#include <glissade/contact/curves/nurbs_curve.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/plotting.h>
#include <glissade/mesh/nurbs_patch.h>
#include <glissade/scene/scene_reader.h>

#include <paper_studies/geometric_study.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    using CurvePoint = MasterCurve::Point;

    CurvePoint
    on_circle(const double theta)
    {
      return {{std::cos(theta), std::sin(theta)}};
    }

    /**
     * The outer edge of the half ring, nodes ordered clockwise (theta from
     * pi down to 0) so that n = e3 x t points out of the ring.
     */
    std::unique_ptr<MasterCurve>
    build_curve(const std::string &method, const unsigned int n_e)
    {
      const double            d_theta = M_PI / n_e;
      std::vector<CurvePoint> vertices;
      for (unsigned int i = 0; i <= n_e; ++i)
        vertices.push_back(on_circle(M_PI - i * d_theta));

      if (method == "q4")
        {
          auto curve = std::make_unique<FacetedCurve>(false);
          curve->update(vertices);
          return curve;
        }
      if (method == "q8" || method == "q12")
        {
          const unsigned int      degree = (method == "q8" ? 2 : 3);
          std::vector<CurvePoint> edge_nodes;
          for (unsigned int i = 0; i < n_e; ++i)
            for (unsigned int j = 1; j < degree; ++j)
              edge_nodes.push_back(
                on_circle(M_PI - (i + double(j) / degree) * d_theta));
          auto curve = std::make_unique<LagrangeEdgeCurve>(degree, false);
          curve->update(vertices, edge_nodes);
          return curve;
        }
      if (method == "bspline")
        {
          auto curve = std::make_unique<BSplineCurve>(
            BSplineCurve::EndCondition::double_vertex);
          curve->update(vertices);
          return curve;
        }
      if (method == "hermite")
        {
          // theta(s) = theta_i - s d_theta on a segment, so
          // dX/ds = d_theta (sin theta, -cos theta).
          std::vector<CurvePoint> tangents;
          for (unsigned int i = 0; i <= n_e; ++i)
            {
              const double theta = M_PI - i * d_theta;
              tangents.push_back(
                {{d_theta * std::sin(theta), -d_theta * std::cos(theta)}});
            }
          auto curve = std::make_unique<HermiteCurve>(false);
          curve->update(vertices);
          curve->set_node_tangents(tangents);
          return curve;
        }
      if (method == "nurbs2" || method == "nurbs3")
        {
          // The half ring as an isogeometric body builds it (Mesh/Type =
          // half ring, Element/Space = nurbs): its outer side, eta along
          // theta from 0 to pi, taken clockwise (each span reversed), with
          // the knots at the n_e equal angles.
          const unsigned int degree = method == "nurbs2" ? 2 : 3;
          const NurbsPatch   patch  = NurbsPatch::annulus(
            Point<2>(), 0.5, 1., 0., M_PI, false, degree, 1, n_e);
          std::map<unsigned int, unsigned int> local;
          std::vector<CurvePoint>              controls;
          std::vector<NurbsCurve::Segment>     segments;
          for (unsigned int i = 0; i < n_e; ++i)
            {
              const auto          side = patch.side_span(0, n_e - 1 - i, 1);
              NurbsCurve::Segment segment{{}, side.weights, side.knots, true};
              for (unsigned int m = 0; m <= degree; ++m)
                {
                  const auto [at, added] =
                    local.emplace(side.controls[m], controls.size());
                  if (added)
                    controls.push_back(
                      {{side.points[m][0], side.points[m][1]}});
                  segment.controls.push_back(at->second);
                }
              segments.push_back(std::move(segment));
            }
          auto curve =
            std::make_unique<NurbsCurve>(degree, false, std::move(segments));
          curve->update(controls);
          return curve;
        }
      throw InputError("Geometric study/Methods",
                       "unknown method '" + method +
                         "' (known: q4, q8, q12, bspline, hermite, nurbs2, "
                         "nurbs3)");
    }
  } // namespace



  const std::vector<std::string> &
  GeometricStudy::methods()
  {
    static const std::vector<std::string> names = {
      "q4", "q8", "q12", "bspline", "hermite", "nurbs2", "nurbs3"};
    return names;
  }



  std::vector<GeometricSample>
  GeometricStudy::evaluate(const std::string &method,
                           const unsigned int n_e,
                           const unsigned int samples_per_edge)
  {
    if (n_e % 2 != 0 || n_e < 4)
      throw InputError("Geometric study/Element counts",
                       "n_e must be even and at least 4, so that a node "
                       "sits at theta = pi/2");
    const auto                   curve = build_curve(method, n_e);
    std::vector<GeometricSample> samples;
    // Clockwise order: segment n_e/2 - 1 ends at pi/2, segment n_e/2 starts
    // there.
    for (unsigned int edge = 1; edge <= 2; ++edge)
      {
        const unsigned int segment = n_e / 2 - (edge == 1 ? 1 : 0);
        for (unsigned int k = 0; k < samples_per_edge; ++k)
          {
            const double s = double(k) / (samples_per_edge - 1);
            CurvePoint   c, dc, ddc;
            curve->evaluate(segment, s, c, dc, ddc);
            const CurvePoint n            = curve->unit_normal(segment, s);
            const double     radius       = std::hypot(c[0], c[1]);
            const CurvePoint exact_normal = {{c[0] / radius, c[1] / radius}};
            GeometricSample  sample;
            sample.edge              = edge;
            sample.xi                = 2. * s - 1.;
            sample.theta             = std::atan2(c[1], c[0]);
            sample.gap_error_percent = 100. * (radius - 1.);
            sample.normal_error_degrees =
              180. / M_PI *
              std::atan2(exact_normal[0] * n[1] - exact_normal[1] * n[0],
                         exact_normal[0] * n[0] + exact_normal[1] * n[1]);
            samples.push_back(sample);
          }
      }
    return samples;
  }



  double
  GeometricStudy::normal_jump_degrees(
    const std::vector<GeometricSample> &samples)
  {
    // The last sample of edge 1 and the first of edge 2 are both at pi/2.
    double end_of_first = 0., start_of_second = 0.;
    bool   found = false;
    for (unsigned int i = 0; i + 1 < samples.size(); ++i)
      if (samples[i].edge == 1 && samples[i + 1].edge == 2)
        {
          end_of_first    = samples[i].normal_error_degrees;
          start_of_second = samples[i + 1].normal_error_degrees;
          found           = true;
        }
    return found ? start_of_second - end_of_first : 0.;
  }



  double
  GeometricStudy::max_gap_error_percent(
    const std::vector<GeometricSample> &samples)
  {
    double m = 0.;
    for (const auto &s : samples)
      m = std::max(m, std::abs(s.gap_error_percent));
    return m;
  }



  double
  GeometricStudy::max_normal_error_degrees(
    const std::vector<GeometricSample> &samples)
  {
    double m = 0.;
    for (const auto &s : samples)
      m = std::max(m, std::abs(s.normal_error_degrees));
    return m;
  }



  double
  GeometricStudy::convergence_order(const std::vector<unsigned int> &n,
                                    const std::vector<double>       &errors)
  {
    double sx = 0., sy = 0., sxx = 0., sxy = 0.;
    for (unsigned int i = 0; i < n.size(); ++i)
      {
        const double x = std::log(double(n[i]));
        const double y = std::log(errors[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
    const double m = n.size();
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
  }



  void
  GeometricStudy::run(const std::string              &prm_file,
                      const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Study", "geometric", Patterns::Selection("geometric"));
    prm.enter_subsection("Geometric study");
    prm.declare_entry("Element counts",
                      "16, 18, 20, 22, 24, 26, 28, 30",
                      Patterns::List(Patterns::Integer(4), 2),
                      "Even numbers of elements along the half ring.");
    prm.declare_entry("Methods",
                      "q4, q8, q12, bspline, hermite, nurbs2, nurbs3",
                      Patterns::List(Patterns::Selection(
                        "q4|q8|q12|bspline|hermite|nurbs2|nurbs3")),
                      "Discretisations of the outer edge (nurbs2, nurbs3: "
                      "the exact NURBS boundary of degree 2, 3).");
    prm.declare_entry("Samples per edge",
                      "41",
                      Patterns::Integer(3),
                      "Points per edge at which the errors are evaluated.");
    prm.declare_entry("Output directory",
                      "output/geometric_study",
                      Patterns::Anything(),
                      "Where CSVs and PNGs go.");
    prm.leave_subsection();
    SceneReader::parse_study(prm, prm_file, overrides);

    prm.enter_subsection("Geometric study");
    std::vector<unsigned int> counts;
    for (const auto &c :
         Utilities::split_string_list(prm.get("Element counts"), ','))
      counts.push_back(Utilities::string_to_int(c));
    const auto methods = Utilities::split_string_list(prm.get("Methods"), ',');
    const unsigned int samples =
      SceneReader::get_integer(prm, "Samples per edge", prm_file);
    const std::string directory = prm.get("Output directory");
    prm.leave_subsection();
    std::filesystem::create_directories(directory);

    AtomicFile curves(directory + "/geometric_study.csv");
    curves.stream() << "method,n_e,edge,xi,theta,gap_error_percent,"
                       "normal_error_degrees\n";
    AtomicFile summary(directory + "/geometric_study_max.csv");
    summary.stream() << "method,n_e,max_gap_error_percent,"
                        "max_normal_error_degrees,normal_jump_degrees\n";

    std::cout << "Geometric study (paper section 3.3), half ring, the two "
                 "edges around theta = pi/2\n"
              << std::setw(8) << "method" << std::setw(6) << "n_e"
              << std::setw(16) << "max|g| (%)" << std::setw(16)
              << "max|dtheta| (o)" << std::setw(18) << "jump at pi/2 (o)"
              << '\n';
    for (const auto &method : methods)
      {
        std::vector<double> gap_errors, normal_errors;
        for (const unsigned int n_e : counts)
          {
            const auto result = evaluate(method, n_e, samples);
            for (const auto &s : result)
              curves.stream()
                << method << ',' << n_e << ',' << s.edge << ',' << s.xi << ','
                << s.theta << ',' << s.gap_error_percent << ','
                << s.normal_error_degrees << '\n';
            gap_errors.push_back(max_gap_error_percent(result));
            normal_errors.push_back(max_normal_error_degrees(result));
            summary.stream() << method << ',' << n_e << ',' << gap_errors.back()
                             << ',' << normal_errors.back() << ','
                             << normal_jump_degrees(result) << '\n';
            std::cout << std::setw(8) << method << std::setw(6) << n_e
                      << std::setw(16) << std::setprecision(4)
                      << gap_errors.back() << std::setw(16)
                      << normal_errors.back() << std::setw(18)
                      << normal_jump_degrees(result) << '\n';
          }
        // (An exact representation's errors are round-off: no order.)
        if (counts.size() >= 2 &&
            *std::max_element(gap_errors.begin(), gap_errors.end()) > 1e-10)
          std::cout << std::setw(8) << method << "  measured order: gap "
                    << std::setprecision(3)
                    << convergence_order(counts, gap_errors) << ", normal "
                    << convergence_order(counts, normal_errors) << "\n";
      }
    curves.commit();
    summary.commit();
    std::cout << std::flush;
    plot_with_python("plot_geometric_study.py", directory);
  }
} // namespace glissade
