#include "dynamics/stiffness_file.h"

#include "errors/errors.h"
#include "errors/file_names.h"

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <tuple>

namespace gearstiff::dynamics
{
namespace
{
using boost::property_tree::ptree;

std::string format(double value)
{
  std::ostringstream s;
  s.precision(6);
  s << value;
  return s.str();
}

ptree read_json(const std::string& path, const std::string& parameter)
{
  if (path.empty())
    throw InputError(parameter, "names no file (the summary.json of `gearstiff stiffness` or "
                                "`gearstiff cai` run with -o)");
  check_file_name(path, parameter);
  std::error_code error; // the throwing overloads ended as std::filesystem's text, exit 1
  if (std::filesystem::is_directory(path, error))
    throw InputError(parameter, "'" + path + "' is a folder, not a file (the summary.json in it?)");
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(parameter, "file '" + path + "' does not exist");
  ptree tree;
  try
  {
    boost::property_tree::read_json(path, tree);
  }
  catch (const boost::property_tree::json_parser_error& e)
  {
    throw InputError(parameter, "'" + path + "' is not JSON (line " + std::to_string(e.line()) +
                                    ": " + e.message() + ")");
  }
  return tree;
}

// Child `key` of a table's node (columns, units, rows): a table without it is no table of
// `gearstiff stiffness` (get_child's "No such node (rows)" ended with exit 1).
const ptree& table_part(const ptree& table_node, const std::string& table, const std::string& key,
                        const std::string& parameter)
{
  const auto part = table_node.get_child_optional(key);
  if (!part)
    throw InputError(parameter, "table " + table + " has no '" + key +
                                    "' (a summary.json of `gearstiff stiffness`/`cai` -o?)");
  return *part;
}

// values/<key>/value as a number, nothing when absent or null.
std::optional<double> value(const ptree& tree, const std::string& key)
{
  const auto node = tree.get_optional<double>(ptree::path_type("values/" + key + "/value", '/'));
  return node ? std::optional<double>(*node) : std::nullopt;
}

StiffnessFilePair read_pair(const ptree& tree, const std::string& path,
                            const std::string& parameter)
{
  const auto z1 = value(tree, "pinion_teeth"), z2 = value(tree, "wheel_teeth"),
             m = value(tree, "transverse_module"), a = value(tree, "centre_distance"),
             eps = value(tree, "contact_ratio");
  if (!z1 || !z2 || !m || !a || !eps)
    throw InputError(parameter, "'" + path +
                                    "' does not name its gear pair (values pinion_teeth, "
                                    "wheel_teeth, transverse_module, centre_distance, "
                                    "contact_ratio of `gearstiff stiffness`/`cai` -o)");
  for (const auto& [key, v] : {std::pair{"pinion_teeth", *z1}, std::pair{"wheel_teeth", *z2},
                               std::pair{"transverse_module", *m}, std::pair{"centre_distance", *a},
                               std::pair{"contact_ratio", *eps}})
    if (!std::isfinite(v) || !(std::abs(v) > 0.) || std::abs(v) > 1e6)
      throw InputError(parameter, "'" + path + "': value " + key + " = " + format(v) +
                                      " is not a finite non-zero number of a gear pair");
  StiffnessFilePair pair{static_cast<int>(std::lround(*z1)), static_cast<int>(std::lround(*z2)),
                         *m * 1e-3, *a * 1e-3, *eps};
  // The model takes both ratios from the file: checked here, so that the message names the
  // file, not the mesh's own 'contact ratio' (as the torsional model's check did).
  if (!(pair.contact_ratio >= 1. && pair.contact_ratio < 4.))
    throw InputError(parameter, "'" + path + "': value contact_ratio = " +
                                    format(pair.contact_ratio) + " must lie in [1, 4)");
  if (const auto approach = value(tree, "approach_ratio"))
  {
    if (!(*approach >= 0. && *approach <= pair.contact_ratio))
      throw InputError(parameter, "'" + path + "': value approach_ratio = " + format(*approach) +
                                      " must lie in [0, contact_ratio]");
    pair.approach_ratio = *approach;
  }
  if (const auto radius = value(tree, "pinion_base_radius"))
    pair.pinion_base_radius = *radius * 1e-3;
  if (const auto torque = value(tree, "pinion_torque"); torque && *torque > 0.)
    pair.pinion_torque = *torque;
  return pair;
}

// Column `name` of table `table`, in the unit `unit`; empty when the table is absent.
std::vector<double> column(const ptree& tree, const std::string& table, const std::string& name,
                           const std::string& unit, const std::string& parameter)
{
  const auto node = tree.get_child_optional(ptree::path_type("tables/" + table, '/'));
  if (!node)
    return {};
  std::vector<std::string> columns, units;
  for (const auto& c : table_part(*node, table, "columns", parameter))
    columns.push_back(c.second.data());
  for (const auto& u : table_part(*node, table, "units", parameter))
    units.push_back(u.second.data());
  const auto found = std::find(columns.begin(), columns.end(), name);
  const std::size_t index = found - columns.begin();
  if (found == columns.end() || index >= units.size() || units[index] != unit)
    throw InputError(parameter, "table " + table + " has no column " + name + " [" + unit + "]");
  std::vector<double> values;
  for (const auto& row : table_part(*node, table, "rows", parameter))
  {
    auto cell = row.second.begin();
    std::advance(cell, std::min(index, row.second.size()));
    if (cell == row.second.end())
      throw InputError(parameter, "table " + table + " has a short row");
    try
    {
      values.push_back(std::stod(cell->second.data()));
    }
    catch (const std::exception&)
    {
      throw InputError(parameter, "table " + table + ": '" + cell->second.data() + "' in column " +
                                      name + " is not a number");
    }
    // NaN or inf anywhere in the table is no measurement (a NaN position was wrapped to 0).
    if (!std::isfinite(values.back()))
      throw InputError(parameter, "table " + table + ": '" + cell->second.data() + "' in column " +
                                      name + " is not a finite number");
  }
  return values;
}

bool has_column(const ptree& tree, const std::string& table, const std::string& name,
                const std::string& parameter)
{
  const auto node = tree.get_child_optional(ptree::path_type("tables/" + table, '/'));
  if (!node)
    return false;
  for (const auto& c : table_part(*node, table, "columns", parameter))
    if (c.second.data() == name)
      return true;
  return false;
}

// The loaded TE s [um] of a sweep and its unloaded TE e [um] (each may be empty).
struct SweepErrors
{
  std::vector<double> loaded;
  std::vector<double> unloaded;
};

// The sweep's k(x) with positions modulo the period (one base pitch, or P of a revolution
// table), checked to cover the cycle; with the loaded TE (may be empty) also its split into
// k and e (nonlinear_mesh.h). `lost_contact` (empty: none) flags rows without contact (k = 0).
MeshStiffness sweep_table(const std::vector<double>& positions,
                          const std::vector<double>& stiffness, const SweepErrors& errors,
                          const std::string& parameter,
                          std::optional<LoadedTransmissionErrorSplit>& split,
                          unsigned int period = 1, const std::vector<double>& lost_contact = {})
{
  const double span = period;
  const auto at = [](const std::vector<double>& v, std::size_t i)
  { return i < v.size() ? v[i] * 1e-6 : 0.; };
  // x [base pitches], k [N/m], s [m], e [m], no contact
  std::vector<std::tuple<double, double, double, double, bool>> nodes;
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    const double x = positions[i] - span * std::floor(positions[i] / span);
    nodes.emplace_back(x < span ? x : 0., stiffness[i] * 1e6, at(errors.loaded, i),
                       at(errors.unloaded, i), i < lost_contact.size() && lost_contact[i] != 0.);
  }
  std::sort(nodes.begin(), nodes.end());
  std::vector<double> x, k, s, e;
  std::vector<bool> lost;
  for (const auto& [xi, ki, si, ei, li] : nodes)
    if (x.empty() || xi - x.back() > 1e-9)
    {
      x.push_back(xi);
      k.push_back(ki);
      s.push_back(si);
      e.push_back(ei);
      lost.push_back(li);
    }
  double widest = x.empty() ? span : span - x.back() + x.front();
  for (std::size_t i = 1; i < x.size(); ++i)
    widest = std::max(widest, x[i] - x[i - 1]);
  if (x.size() < 3 || widest > 2. * span / x.size())
    throw InputError(
        parameter, "the table does not cover a mesh cycle: " + std::to_string(x.size()) +
                       " distinct positions modulo " +
                       (period == 1 ? std::string("one base pitch")
                                    : std::to_string(period) + " base pitches") +
                       ", widest gap " + format(widest) + " base pitches (at most twice the mean " +
                       "spacing allowed; sweep one full base pitch)");
  // The stiffness values are checked (range of real gear meshes) before the TE split uses them.
  MeshStiffness table = MeshStiffness::table(x, k, parameter, period,
                                             lost_contact.empty() ? std::vector<bool>() : lost);
  if (!errors.loaded.empty())
    split = split_loaded_transmission_error(
        x, k, s, errors.unloaded.empty() ? std::vector<double>() : e, parameter);
  return table;
}

// The revolution table of `gearstiff faults` (docs/faults.md): columns mesh_position [-],
// stiffness [N/um], lost_contact [-] and period [-] (base pitches, the faulty gear's teeth, the
// same on every row and equal to the tooth count of one gear of the file's pair).
MeshStiffness revolution_table(const ptree& tree, const StiffnessFilePair& pair,
                               const std::vector<double>& positions, const std::string& parameter)
{
  const std::string table = "revolution_stiffness";
  const std::vector<double> periods = column(tree, table, "period", "-", parameter);
  const double period = periods.front();
  for (const double p : periods)
    if (p != period)
      throw InputError(parameter, "table " + table + ": the column period differs between rows (" +
                                      format(period) + " and " + format(p) + ")");
  if (!(period == std::abs(pair.pinion_teeth) || period == std::abs(pair.wheel_teeth)))
    throw InputError(parameter, "table " + table + ": period " + format(period) +
                                    " base pitches is neither gear's tooth count (z1 = " +
                                    std::to_string(pair.pinion_teeth) +
                                    ", z2 = " + std::to_string(pair.wheel_teeth) +
                                    "): a revolution table spans one revolution of the faulty "
                                    "gear, its tooth count of base pitches");
  std::optional<LoadedTransmissionErrorSplit> no_split;
  return sweep_table(positions, column(tree, table, "stiffness", "N/um", parameter), {}, parameter,
                     no_split, static_cast<unsigned int>(period),
                     column(tree, table, "lost_contact", "-", parameter));
}
} // namespace

std::string StiffnessFilePair::describe() const
{
  return "z " + std::to_string(pinion_teeth) + "/" + std::to_string(wheel_teeth) + ", m_t " +
         format(module * 1e3) + " mm, a_w " + format(centre_distance * 1e3) + " mm";
}

StiffnessFile read_stiffness_file(const std::string& path, const std::string& parameter)
{
  const ptree tree = read_json(path, parameter);
  StiffnessFile file;
  file.command = tree.get<std::string>("command", "");
  file.pair = read_pair(tree, path, parameter);
  const std::vector<double> positions =
      column(tree, "stiffness_sweep", "mesh_position", "-", parameter);
  if (!positions.empty())
  {
    const auto optional_column = [&](const std::string& name)
    {
      return has_column(tree, "stiffness_sweep", name, parameter)
                 ? column(tree, "stiffness_sweep", name, "um", parameter)
                 : std::vector<double>();
    };
    // The unloaded TE of the modifications travels with the loaded one: k = W/(s − e).
    const std::vector<double> loaded_error = optional_column("transmission_error");
    const std::vector<double> unloaded_error = loaded_error.empty()
                                                   ? std::vector<double>()
                                                   : optional_column("unloaded_transmission_error");
    file.stiffness =
        sweep_table(positions, column(tree, "stiffness_sweep", "stiffness", "N/um", parameter),
                    {loaded_error, unloaded_error}, parameter, file.transmission_error);
    return file;
  }
  const std::vector<double> revolution =
      column(tree, "revolution_stiffness", "mesh_position", "-", parameter);
  if (!revolution.empty())
  {
    file.stiffness = revolution_table(tree, file.pair, revolution, parameter);
    return file;
  }
  const auto scale = value(tree, "cai_scale");
  const auto c0 = value(tree, "cai_c0"), c1 = value(tree, "cai_c1"), c2 = value(tree, "cai_c2");
  if (!scale || !c0 || !c1 || !c2)
    throw InputError(parameter, "'" + path +
                                    "' holds no mesh stiffness (the table stiffness_sweep of "
                                    "`gearstiff stiffness` in mode sweep, revolution_stiffness "
                                    "of `gearstiff faults`, or the Cai values of `gearstiff "
                                    "cai`)");
  CaiParameters cai;
  cai.scale = *scale * 1e6;
  cai.shape = {*c0, *c1, *c2};
  file.stiffness = MeshStiffness::cai(cai, parameter);
  return file;
}

unsigned int match_stiffness_file(const StiffnessFile& file, int teeth_a, int teeth_b,
                                  double module, double centre_distance,
                                  const std::string& parameter)
{
  const StiffnessFilePair& p = file.pair;
  const auto close = [](double u, double v) { return std::abs(u - v) <= 1e-6 * std::abs(v); };
  const bool same_size = close(p.module, module) && close(p.centre_distance, centre_distance);
  // An external pinion meshes the internal wheel; two external gears in either order.
  for (unsigned int pinion = 0; pinion < 2; ++pinion)
  {
    const int z_pinion = pinion == 0 ? teeth_a : teeth_b;
    const int z_wheel = pinion == 0 ? teeth_b : teeth_a;
    if (same_size && z_pinion == p.pinion_teeth && z_wheel == p.wheel_teeth)
      return pinion;
  }
  StiffnessFilePair mesh{teeth_a, teeth_b, module, centre_distance, 0.};
  throw InputError(parameter, "the table belongs to another pair: file " + p.describe() +
                                  ", this mesh " + mesh.describe());
}
} // namespace gearstiff::dynamics
