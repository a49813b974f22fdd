// The unit responses a rolling sweep keeps (ContactProblem::roll, contact/contact_problem.h
// "Rolling"): the rows they are kept at, their bounded memory and the new columns of a position.
// The rest of the Schur-complement path is contact/contact_condensed.cc.
#include "contact/contact_problem_internal.h"
#include "errors/errors.h"

#include <Eigen/Dense>
#include <algorithm>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <iterator>
#include <map>

namespace gearstiff::contact
{
using namespace dealii;

namespace
{
// Bounded memory of the kept unit responses of a rolling sweep (a 3D flank set holds many rows,
// 28k on the default 3D Q1 pair): past this, those unused the longest are dropped.
constexpr std::size_t max_kept_values = 60'000'000; // 480 MB

// 2D rolling: every block of unit responses costs a fixed ~6 ms of MUMPS set-up on the
// 131k-DoF scene besides ~1 ms per column, and a window moves a small part of its radius per
// position; so a block also takes the columns of every node within half its window's radius
// (the closed zone's bound, closed_within_windows) and of its masters: the nodes about to close
// come in few blocks. 3D columns cost far more each: only those asked for.
template <int dim, typename Pairs>
std::vector<types::global_dof_index> window_prefetch(const Pairs& pairs)
{
  std::vector<types::global_dof_index> dofs;
  if (dim != 2)
    return dofs;
  for (const auto& pair : pairs)
    if (pair.window.radius > 0.)
      for (const auto& node : pair.nodes)
        if (pair.window.distance(node.node.position) <= 0.5 * pair.window.radius)
          for (unsigned int d = 0; d < dim; ++d)
          {
            dofs.push_back(node.node.dofs[d]);
            for (const auto& master : node.masters)
              dofs.push_back(master.node.dofs[d]);
          }
  return dofs;
}
} // namespace

template <int dim>
void ContactProblem<dim>::keep_columns_on(const std::vector<types::boundary_id>& surfaces)
{
  rolling_surfaces = surfaces;
}

template <int dim>
std::vector<types::global_dof_index>
ContactProblem<dim>::surface_dofs(const std::vector<types::boundary_id>& ids) const
{
  std::vector<types::global_dof_index> dofs, face_dofs;
  for (const auto& cell : elastic.get_dof_handler().active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) != ids.end())
      {
        face_dofs.resize(cell->get_fe().n_dofs_per_face(f));
        cell->face(f)->get_dof_indices(face_dofs);
        dofs.insert(dofs.end(), face_dofs.begin(), face_dofs.end());
      }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

template <int dim>
std::shared_ptr<typename ContactProblem<dim>::RowSet>
ContactProblem<dim>::rows_for_new_responses(Condensed& c) const
{
  // The surfaces the sweep pairs: those declared and those of the current pairs.
  std::vector<types::boundary_id> ids = rolling_surfaces;
  double window = 0.; // m, the largest window radius
  bool windowed = !pairs.empty();
  for (const auto& pair : pairs)
  {
    ids.insert(ids.end(), pair.slave.begin(), pair.slave.end());
    ids.insert(ids.end(), pair.master.begin(), pair.master.end());
    windowed = windowed && pair.window.radius > 0.;
    window = std::max(window, pair.window.radius);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids != c.surface_ids)
  {
    c.surface_ids = ids;
    c.surface_rows = surface_dofs(ids);
  }
  // 2D: the rows of every swept surface, one set for the whole sweep (a column costs ~1 ms
  // whatever its rows). 3D: a column costs with the rows asked for (MUMPS prunes the backward
  // solve to their elimination-tree paths): default pair, Q1, 8 layers, 457k DoFs, 32 positions
  // on 2 ranks, per column and rank: every swept flank and the reported rows (28k rows) 17 ms;
  // the contact DoFs alone (~9k) 9 ms, but a kept response then lacks the next window's rows
  // and is computed again (14.9k columns a rank instead of 8.7k); the contact DoFs and the
  // flank rows within a quarter (~11k rows) or half (~12k) a window radius of them 12 and
  // 13.5 ms, 8.9k and 8.6k columns: a quarter. A node stays closed over a position or two,
  // while its window moves ~0.23 mm (a quarter radius) at each.
  const bool whole_surfaces = dim == 2 || !windowed;
  if (whole_surfaces && c.new_rows && c.covers_targets(*c.new_rows))
    return c.new_rows;
  if (!whole_surfaces && c.new_rows && c.new_rows->built == c.pairing)
    return c.new_rows;
  auto rows = std::make_shared<RowSet>();
  const std::vector<types::global_dof_index> near =
      whole_surfaces ? c.surface_rows : rows_near_targets(c, 0.25 * window);
  std::set_union(near.begin(), near.end(), c.targets.begin(), c.targets.end(),
                 std::back_inserter(rows->rows));
  rows->built = c.pairing;
  c.new_rows = rows;
  return rows;
}

template <int dim>
std::vector<types::global_dof_index>
ContactProblem<dim>::rows_near_targets(const Condensed& c, const double distance) const
{
  // The surface rows within `distance` of a contact DoF (reference positions: a body turns
  // rigidly, so its distances stay), found through a grid of cells of that size.
  const std::vector<Point<dim>>& points = elastic.support_points();
  const auto cell_of = [&](const Point<dim>& p)
  {
    std::array<long long, dim> cell;
    for (unsigned int d = 0; d < dim; ++d)
      cell[d] = static_cast<long long>(std::floor(p[d] / distance));
    return cell;
  };
  std::map<std::array<long long, dim>, std::vector<Point<dim>>> grid;
  for (const auto dof : c.dofs)
    grid[cell_of(points[dof])].push_back(points[dof]);
  std::vector<types::global_dof_index> near;
  for (const auto dof : c.surface_rows)
  {
    const Point<dim>& p = points[dof];
    const std::array<long long, dim> centre = cell_of(p);
    bool found = false;
    for (unsigned int k = 0; k < (dim == 2 ? 9u : 27u) && !found; ++k)
    {
      std::array<long long, dim> cell = centre;
      for (unsigned int d = 0, code = k; d < dim; ++d, code /= 3)
        cell[d] += static_cast<long long>(code % 3) - 1;
      if (const auto points_there = grid.find(cell); points_there != grid.end())
        found = std::any_of(points_there->second.begin(), points_there->second.end(),
                            [&](const Point<dim>& q) { return p.distance(q) <= distance; });
    }
    if (found)
      near.push_back(dof);
  }
  return near;
}

template <int dim>
void ContactProblem<dim>::make_room_for_columns(Condensed& c, std::size_t n_new) const
{
  // Drops the kept responses of earlier pairings, those unused the longest first, until
  // `n_new` more values fit in max_kept_values (or none of an earlier pairing is left: the
  // current pairing's loads need theirs, and complete_at_kept_rows reads them after the last
  // solve). The rolling positions of one rank follow each other (stiffness::stiffness_sweep),
  // so the responses of the nearest earlier positions, the ones the next pairing shares, stay.
  std::vector<std::pair<unsigned int, types::global_dof_index>> earlier; // (pairing, DoF)
  for (const auto& [dof, kept] : c.unit_columns)
    if (kept.last_use < c.pairing)
      earlier.emplace_back(kept.last_use, dof);
  std::sort(earlier.begin(), earlier.end());
  for (const auto& [used, dof] : earlier)
  {
    if (c.kept_values + n_new <= max_kept_values)
      break;
    c.kept_values -= c.unit_columns.at(dof).values.size();
    c.unit_columns.erase(dof);
  }
}

template <int dim>
std::vector<std::vector<double>> ContactProblem<dim>::rolling_columns(
    const std::vector<std::vector<std::pair<types::global_dof_index, double>>>& loads)
{
  Condensed& c = *condensed;
  // The current loads' kept responses are marked used (make_room_for_columns keeps them); the
  // others, and those whose rows miss a target, are computed below, marked used too.
  const auto usable = [&](const types::global_dof_index dof)
  {
    const auto kept = c.unit_columns.find(dof);
    return kept != c.unit_columns.end() && c.covers_targets(*kept->second.rows) ? &kept->second
                                                                                : nullptr;
  };
  std::vector<types::global_dof_index> missing;
  for (const auto& load : loads)
    for (const auto& [dof, weight] : load)
      if (auto* kept = usable(dof))
        kept->last_use = c.pairing;
      else
        missing.push_back(dof);
  if (!missing.empty())
    for (const types::global_dof_index dof : window_prefetch<dim>(pairs))
      if (!usable(dof))
        missing.push_back(dof);
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  if (!missing.empty())
  {
    const std::shared_ptr<RowSet> rows = rows_for_new_responses(c);
    for (const auto dof : missing)
      if (const auto stale = c.unit_columns.find(dof); stale != c.unit_columns.end())
      {
        c.kept_values -= stale->second.values.size();
        c.unit_columns.erase(stale);
      }
    if (c.kept_values + missing.size() * rows->rows.size() > max_kept_values)
      make_room_for_columns(c, missing.size() * rows->rows.size());
    std::vector<fem::SparseLoad> units;
    for (const auto dof : missing)
      units.push_back({{dof, 1.}});
    std::vector<std::vector<double>> responses = c.factorization->responses(units, rows->rows);
    for (unsigned int j = 0; j < missing.size(); ++j)
    {
      c.kept_values += responses[j].size();
      c.unit_columns.emplace(
          missing[j], typename Condensed::KeptResponse{std::move(responses[j]), rows, c.pairing});
    }
    c.covers_targets(*rows);
  }
  std::vector<std::vector<double>> columns(loads.size(), std::vector<double>(c.dofs.size(), 0.));
  for (unsigned int j = 0; j < loads.size(); ++j)
    for (const auto& [dof, weight] : loads[j])
    {
      const typename Condensed::KeptResponse& unit = c.unit_columns.at(dof);
      const std::vector<int>& at = unit.rows->of_target;
      for (unsigned int i = 0; i < c.dofs.size(); ++i)
        columns[j][i] += weight * unit.values[at[c.contact_target[i]]];
    }
  return columns;
}

template <int dim>
void ContactProblem<dim>::add_new_columns()
{
  // Columns for the nodes closed for the first time, in one block of right-hand sides.
  Condensed& c = *condensed;
  std::vector<fem::SparseLoad> loads;
  std::vector<std::pair<unsigned int, unsigned int>> new_nodes;
  for (unsigned int p = 0; p < pairs.size(); ++p)
    for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
      if (pairs[p].memory[k].state != NodeState::open && c.slot[p][k] < 0)
      {
        new_nodes.emplace_back(p, k);
        const SlaveNode<dim>& node = pairs[p].nodes[k];
        for (unsigned int d = 0; d < dim; ++d)
          if (!node.rotated)
          {
            fem::SparseLoad load{{node.node.dofs[d], 1.}};
            for (const auto& master : node.masters)
              load.emplace_back(master.node.dofs[d], -master.weight);
            loads.push_back(std::move(load));
          }
          else
            loads.push_back(relative_terms(node, d));
      }
  if (loads.empty())
    return;
  std::vector<std::vector<double>> columns =
      rolling ? rolling_columns(loads) : c.factorization->responses(loads, c.dofs);
  for (unsigned int j = 0; j < new_nodes.size(); ++j)
    c.slot[new_nodes[j].first][new_nodes[j].second] = c.columns.size() + j * dim;
  for (auto& column : columns)
    c.columns.push_back(std::move(column));
}

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
