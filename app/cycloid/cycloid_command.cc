// `gearstiff cycloid`: the corrected equidistant of a cycloid (Cyclo) disc for a list of contact
// arc ratios ε (docs/references.md §4, Chmurawa & Łokiec), solved with Levenberg–Marquardt, with
// the roller clearances of each corrected disc and the published ε = 0.27 column beside ours.
//
//   gearstiff cycloid                                      the published disc, ε = 0.27
//   gearstiff cycloid --set "Cycloid correction/contact arc ratios=0.2, 0.27, 0.35"
//   gearstiff cycloid -o out    also writes the disc outlines (CSV) and the tables
#include "app/core/command.h"
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/scenes/geometry_parameters.h"
#include "errors/errors.h"
#include "geometry/cycloid_disc.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

// docs/references.md §4: the one published correction column (ε = 0.27, Δr = 0.01 mm).
struct PublishedColumn
{
  double alpha_1 = 3.484203, alpha_ok_1 = 3.391341, alpha_2 = 8.599992, alpha_ok_2 = 8.567535; // °
  double roller_circle_radius = 96.44742, roller_radius = 9.047590;                            // mm
  double rotation = 0.197962;                                                                  // °
  double shortening = 0.622101;                                                                // -
};

void declare_parameters(ParameterHandler& prm)
{
  declare_cycloid_disc_parameters(prm);
  prm.enter_subsection("Cycloid correction");
  prm.declare_entry(
      "contact arc ratios", "0.27", List(Double(0., 0.5), 1),
      "epsilon: contact arc |alpha2 - alpha1| as a fraction of the lobe pitch 360°/z_s "
      "[-], a comma-separated list, each in (0, 0.5)");
  prm.declare_entry("clearance limit", "0.01", Double(0.),
                    "Delta r, largest clearance to the nominal profile over the contact arc [mm]");
  prm.declare_entry("disc rotation", "0", Double(-360., 360.),
                    "disc rotation psi at which the roller clearances are evaluated [deg]");
  prm.declare_entry("outline points per lobe", "121", Integer(5, 100000),
                    "points per lobe of the disc outline written with -o [-]");
  prm.leave_subsection();
}

std::vector<double> parse_ratios(const std::string& text)
{
  std::vector<double> ratios;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    ratios.push_back(std::stod(item));
  return ratios;
}

void write_outline(std::ostream& out, const geometry::ToothProfile& lobe)
{
  out << "x_mm,y_mm,normal_x,normal_y,arc_length_mm\n" << std::setprecision(12);
  for (const geometry::ProfilePoint& p : geometry::full_outline(lobe))
    out << p.position.x() / mm << ',' << p.position.y() / mm << ',' << p.normal.x() << ','
        << p.normal.y() << ',' << p.arc_length / mm << '\n';
}

struct CorrectionInputs
{
  std::vector<double> ratios;       // -, contact arc ratios ε
  double clearance_limit = 0.;      // m, Δr
  double disc_rotation = 0.;        // rad, ψ of the clearances
  unsigned int points_per_lobe = 0; // -, of the outlines written
};

CorrectionInputs parse_correction_inputs(ParameterHandler& prm)
{
  CorrectionInputs in;
  prm.enter_subsection("Cycloid correction");
  in.ratios = parse_ratios(prm.get("contact arc ratios"));
  in.clearance_limit = prm.get_double("clearance limit") * mm;
  in.disc_rotation = prm.get_double("disc rotation") * degree;
  in.points_per_lobe = prm.get_integer("outline points per lobe");
  prm.leave_subsection();
  return in;
}

void report_nominal_disc(Report& report, const geometry::CycloidDiscSpec& nominal)
{
  report.add_value("shortening_coefficient", geometry::shortening_coefficient(nominal), "-",
                   "m = e·z_k/r of the nominal epicycloid");
  report.add_value("disc_lobes", nominal.rollers - 1, "-", "z_s, lobes of the disc");
  report.add_value("gear_ratio", -(nominal.rollers - 1.), "-",
                   "i = -z_s/(z_k - z_s) with the roller ring fixed");
}

// The disc and correction of docs/references.md §4, whose ε = 0.27 column is published.
bool is_published_case(const geometry::CycloidDiscSpec& nominal, double eps, double clearance_limit)
{
  return std::abs(eps - 0.27) < 1e-12 && std::abs(clearance_limit - 0.01 * mm) < 1e-15 &&
         nominal.rollers == 20 && std::abs(nominal.roller_circle_radius - 96 * mm) < 1e-12 &&
         std::abs(nominal.eccentricity - 3 * mm) < 1e-12 &&
         std::abs(nominal.roller_radius - 8.5 * mm) < 1e-12;
}

void report_published_column(Report& report, const geometry::CycloidCorrection& c)
{
  const PublishedColumn published;
  const std::string source = "docs/references.md §4 (Chmurawa & Łokiec), ε = 0.27";
  report.add_compared_value("alpha_1", c.alpha_1 / degree, published.alpha_1, "deg", "α1", source);
  report.add_compared_value("alpha_ok_1", c.alpha_ok_1 / degree, published.alpha_ok_1, "deg",
                            "α_ok1", source);
  report.add_compared_value("alpha_2", c.alpha_2 / degree, published.alpha_2, "deg", "α2", source);
  report.add_compared_value("alpha_ok_2", c.alpha_ok_2 / degree, published.alpha_ok_2, "deg",
                            "α_ok2", source);
  report.add_compared_value("r_k", c.roller_circle_radius / mm, published.roller_circle_radius,
                            "mm", "corrected roller-circle radius r_k", source);
  report.add_compared_value("q_k", c.roller_radius / mm, published.roller_radius, "mm",
                            "corrected equidistant q_k", source);
  report.add_compared_value("delta", c.rotation / degree, published.rotation, "deg",
                            "rotation δ of the corrected profile", source);
  report.add_compared_value("m_k", c.shortening, published.shortening, "-", "m_k = e·z_k/r_k",
                            source);
}

// The roller clearances of each corrected disc, one column per ε.
struct ClearanceColumns
{
  std::vector<std::string> names{"roller", "roller_angle"};
  std::vector<std::string> units{"-", "deg"};
  std::vector<std::vector<double>> values; // m, per ε, per roller
};

// One ε: its correction row, its clearances, the published comparison, its outline file.
void correct_for_ratio(CommandContext& context, const geometry::CycloidDiscSpec& nominal,
                       const CorrectionInputs& in, double eps, ReportTable& table,
                       ClearanceColumns& clearances)
{
  const auto start = std::chrono::steady_clock::now();
  const geometry::CycloidCorrection c =
      geometry::solve_cycloid_correction(nominal, eps, in.clearance_limit);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  table.add_row({eps, c.alpha_1 / degree, c.alpha_ok_1 / degree, c.alpha_2 / degree,
                 c.alpha_ok_2 / degree, c.alpha_s / degree, c.roller_circle_radius / mm,
                 c.roller_radius / mm, c.rotation / degree, c.shortening, double(c.iterations),
                 double(c.function_evaluations), seconds * 1e3});
  const geometry::CycloidDiscSpec corrected = c.corrected_disc(nominal);
  clearances.values.push_back(geometry::roller_clearances(nominal, corrected, in.disc_rotation));
  std::ostringstream name;
  name << "clearance_eps_" << eps;
  clearances.names.push_back(name.str());
  clearances.units.push_back("mm");

  if (is_published_case(nominal, eps, in.clearance_limit))
    report_published_column(context.report, c);
  if (context.writes_files())
  {
    std::ostringstream file;
    file << "disc_outline_eps_" << eps << ".csv";
    const geometry::ToothProfile lobe =
        geometry::generate_cycloid_disc(corrected, in.points_per_lobe);
    context.write_output(file.str(),
                         "corrected disc outline (points, normals), ε = " + std::to_string(eps),
                         [&](std::ostream& out) { write_outline(out, lobe); });
  }
}

void add_clearance_table(Report& report, const geometry::CycloidDiscSpec& nominal,
                         const ClearanceColumns& clearances)
{
  ReportTable& gaps = report.add_table("roller_clearances", clearances.names, clearances.units);
  for (unsigned int i = 0; i < nominal.rollers; ++i)
  {
    std::vector<double> row{double(i), 360. * i / nominal.rollers};
    for (const auto& column : clearances.values)
      row.push_back(column[i] / mm);
    gaps.add_row(row);
  }
}

void report_method(Report& report, double disc_rotation)
{
  report.add_text(
      "method", "Levenberg-Marquardt (Eigen MINPACK port, central-difference Jacobian) on 8 "
                "equations: clearance Delta r at both arc ends, touching with equal slopes at S, "
                "arc length epsilon*360deg/z_s; r_k = C(q_k - q) + r. Clearances: distance from "
                "each roller centre to the corrected profile minus q, disc at nominal kinematics.");
  report.add_text("roller clearances",
                  "Δr_i at disc rotation ψ = " + format_number(disc_rotation / degree, 6) +
                      "° (Cycloid correction/disc rotation); `gearstiff cycloid-loads` reports the "
                      "same clearance (column gap_*) at the disc rotation of its crank angle, so "
                      "the two agree when ψ does");
}

void run(ParameterHandler& prm, CommandContext& context)
{
  const geometry::CycloidDiscSpec nominal = parse_cycloid_disc_parameters(prm);
  const CorrectionInputs in = parse_correction_inputs(prm);

  // Check the disc before any solving so bad geometry gives one line naming the parameter.
  const geometry::ToothProfile nominal_lobe =
      geometry::generate_cycloid_disc(nominal, in.points_per_lobe);
  Report& report = context.report;
  report_nominal_disc(report, nominal);

  ReportTable& table = report.add_table(
      "cycloid_correction",
      {"epsilon", "alpha_1", "alpha_ok_1", "alpha_2", "alpha_ok_2", "alpha_s", "r_k", "q_k",
       "delta", "m_k", "iterations", "function_evaluations", "solve_time"},
      {"-", "deg", "deg", "deg", "deg", "deg", "mm", "mm", "deg", "-", "-", "-", "ms"});
  ClearanceColumns clearances;
  for (const double eps : in.ratios)
    correct_for_ratio(context, nominal, in, eps, table, clearances);
  add_clearance_table(report, nominal, clearances);
  report_method(report, in.disc_rotation);
  if (context.writes_files())
    context.write_output("disc_outline_nominal.csv", "nominal disc outline",
                         [&](std::ostream& out) { write_outline(out, nominal_lobe); });
}

const CommandRegistration registration(
    {"cycloid", "cycloid disc: corrected equidistant (Levenberg-Marquardt), roller clearances",
     "Computes the correction (r_k, q_k, delta and the contact-arc angles) of a cycloid disc's\n"
     "equidistant for each contact arc ratio epsilon, after Chmurawa & Lokiec (docs/references.md "
     "§4),\n"
     "with the roller clearances of each corrected disc. The built-in case is the published disc\n"
     "(r = 96 mm, e = 3 mm, q = 8.5 mm, z_k = 20) whose epsilon = 0.27 column is compared.\n"
     "With -o: disc outlines (points, outward normals, arc length) as CSV.",
     declare_parameters, run});
} // namespace
