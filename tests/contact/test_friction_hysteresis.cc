// Quasi-static incremental Coulomb friction along a load path (ContactProblem::set_hub_target,
// solve_next_step): a shaft shrink-fitted in a ring, turned back and forth by its bore.
//
// Exact oracle. Both bodies are annuli meshed with the same 48 nodes around, at the same angles,
// so every contact node is the image of every other under a rotation by 2π/48: all nodes carry
// the same pressure and shear and stick or slip together. A uniform shear on a circle causes no
// radial displacement in a linear elastic annulus, so the interference pressure (total normal
// force N) does not change with the torque. The interface is then exactly a rigid-plastic
// element in series with a linear torsional spring: stick with T = k (θ − θ_slip) while
// |T| < T_s = μ N R_m (every friction force is tangential and reaches the shaft at its master
// node, which the slave node faces at the same angle: lever R_m, the shaft radius),
// slip at |T| = T_s. Loading to 1.5 θ_s slips by 0.5 θ_s; unloading sticks again and keeps that
// offset, so T = 0 at θ = 0.5 θ_s (the residual rotation is the slip of the loading phase) where
// the loading branch had T = T_s/2 — the path dependence a frictionless solve cannot show.
#include "contact/contact_problem.h"
#include "fem/mesh.h"

#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::contact;

namespace
{
constexpr double bore = 5e-3, fit = 10e-3, outside = 15e-3; // m, radii
constexpr double interference = 0.5e-6;                     // m, radial
constexpr double slave_radius = fit - interference;         // m
const fem::Material steel{210e9, 0.3};

// Boundary ids: 10 shaft bore (hub), 11 shaft surface (master), 12 ring bore (slave), 13 ring
// outside (fixed).
void make_shrink_fit(Triangulation<2>& tria)
{
  Triangulation<2> shaft, ring;
  // colorize: 0 inner circle, 1 outer circle; one refinement keeps the nodes on the circles.
  GridGenerator::hyper_shell(shaft, Point<2>(), bore, fit, 24, true);
  GridGenerator::hyper_shell(ring, Point<2>(), slave_radius, outside, 24, true);
  shaft.refine_global(1);
  ring.refine_global(1);
  const auto label = [](Triangulation<2>& body, types::material_id material,
                        types::boundary_id inner, types::boundary_id outer)
  {
    for (auto& cell : body.active_cell_iterators())
    {
      cell->set_material_id(material);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(cell->face(f)->boundary_id() == 0 ? inner : outer);
    }
  };
  label(shaft, 1, 10, 11);
  label(ring, 2, 12, 13);
  fem::join_bodies<2>({&shaft, &ring}, tria);
}

struct Path
{
  double stiffness = 0.;         // N·m/rad, k from the first (stick) step
  double slip_torque = 0.;       // N·m, T_s = μ N R_m
  std::vector<double> rotations; // rad
  std::vector<double> torques;   // N·m, on the shaft by its hub
};

// The shaft turned to `fractions` × θ_s in turn (θ_s = T_s/k; for μ = 0 in units of 10 µrad).
Path turn_shaft(double mu, IterationSolves solves, const std::vector<double>& fractions)
{
  fem::ElasticityParameters elasticity;
  elasticity.thickness = 1e-3;
  ContactParameters contact;
  contact.friction_coefficient = mu;
  contact.iteration_solves = solves;
  ContactProblem<2> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(), contact);
  make_shrink_fit(problem.system().triangulation());
  problem.system().set_materials({{1, steel}, {2, steel}}, "materials");
  problem.add_rigid_hub(10, Point<2>(), fem::RigidHub<2>::Control::rotation, 0., "shaft");
  problem.add_displacement(13, Tensor<1, 2>(), "ring");
  problem.add_contact_pair({12}, {11}, "fit");
  problem.run(); // the shrink fit alone
  const auto torque = [&problem]()
  {
    for (const auto& s : problem.results().supports)
      if (s.name == "shaft")
        return s.torque;
    return 0.;
  };

  Path path;
  const double probe = 1e-6; // rad, well inside stick (θ_s ≈ 2e-5 rad at μ = 0.3)
  problem.set_hub_target("shaft", probe);
  problem.solve_next_step();
  path.stiffness = torque() / probe;
  path.slip_torque = mu * problem.results().pairs[0].normal_force * fit;
  const double unit = mu > 0. ? path.slip_torque / path.stiffness : 1e-5; // rad
  for (const double f : fractions)
  {
    problem.set_hub_target("shaft", f * unit);
    problem.solve_next_step();
    path.rotations.push_back(f * unit);
    path.torques.push_back(torque());
  }
  return path;
}

// The exact answer: an elastic–perfectly-plastic torsional element, from T = k·probe.
std::vector<double> coulomb_torques(const Path& path, double probe)
{
  std::vector<double> torques;
  double previous_rotation = probe, previous_torque = path.stiffness * probe;
  for (const double rotation : path.rotations)
  {
    const double trial = previous_torque + path.stiffness * (rotation - previous_rotation);
    previous_torque = std::max(-path.slip_torque, std::min(path.slip_torque, trial));
    previous_rotation = rotation;
    torques.push_back(previous_torque);
  }
  return torques;
}

// θ/θ_s: stick, slip forward, unload in stick to T = 0 (at 0.5), reverse into backward slip,
// reload in stick. No step ends exactly on the bound (the oracle would be undecided there).
const std::vector<double> cycle{0.5, 1.5, 1.0, 0.5, -0.4, -1.5, -0.5, 0.3};
} // namespace

TEST(FrictionHysteresis, ShrinkFitFollowsCoulombAlongTheCycle)
{
  const double mu = 0.3;
  const Path path = turn_shaft(mu, IterationSolves::automatic, cycle);
  ASSERT_GT(path.slip_torque, 0.);
  const std::vector<double> expected = coulomb_torques(path, 1e-6);
  // Tolerance: the friction bounds converge to 1e-8 of the normal force (Friction tolerance)
  // and the stick steps are linear solves; 1e-6 of T_s leaves room for round-off of the 48
  // nodes' symmetric states.
  for (unsigned int k = 0; k < cycle.size(); ++k)
    EXPECT_NEAR(path.torques[k], expected[k], 1e-6 * path.slip_torque) << "step " << k;
  // Path dependence: at 0.5 θ_s the loading branch carries T_s/2, the unloading one nothing —
  // the residual rotation equals the slip of the loading phase, 1.5 θ_s − θ_s.
  EXPECT_NEAR(path.torques[0], 0.5 * path.slip_torque, 1e-6 * path.slip_torque);
  EXPECT_NEAR(path.torques[3], 0., 1e-6 * path.slip_torque);
  // Slipping steps sit on the Coulomb bound, in the sense of the motion.
  EXPECT_NEAR(path.torques[1], path.slip_torque, 1e-6 * path.slip_torque);
  EXPECT_NEAR(path.torques[5], -path.slip_torque, 1e-6 * path.slip_torque);
}

TEST(FrictionHysteresis, SchurComplementAndFullResolveAgree)
{
  // set_hub_target adds the hub's unit response to the one factorization (Schur complement)
  // or rebuilds the constraints (full re-solve): the same constrained minimum to round-off.
  const std::vector<double> steps{1.5, 0.5, -1.5};
  const Path schur = turn_shaft(0.3, IterationSolves::schur_complement, steps);
  const Path full = turn_shaft(0.3, IterationSolves::full_resolve, steps);
  for (unsigned int k = 0; k < steps.size(); ++k)
    EXPECT_NEAR(schur.torques[k], full.torques[k], 1e-8 * schur.slip_torque) << "step " << k;
}

TEST(FrictionHysteresis, FrictionlessLoopCloses)
{
  // μ = 0: the shaft turns freely in its fit, the torque is round-off at every step and the
  // loop has no width. A stuck shaft would carry k·θ ≈ 3e4 N·m/rad × 1e-5 rad = 0.3 N·m at these
  // rotations; 1e-9 N·m is round-off of that.
  const Path path = turn_shaft(0., IterationSolves::automatic, cycle);
  for (unsigned int k = 0; k < cycle.size(); ++k)
    EXPECT_NEAR(path.torques[k], 0., 1e-9) << "step " << k;
}
