// Errors and results across MPI ranks (fem/parallel.h), on 2 ranks: a failure of one rank is
// thrown on every rank with its type, parameter or method and reason; the first failure by
// order wins; results cross ranks through their `serialize` functions with every field intact;
// a sweep whose positions are all refused stops every rank with the first position's error.
// Exact oracles: the values and texts put in on one rank must come out on the other.
#include "errors/errors.h"
#include "fem/parallel.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "tests/stiffness/work_file.h"

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/utilities.h>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace gearstiff;

namespace
{
unsigned int rank()
{
  return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
}
} // namespace

TEST(ParallelErrors, NoFailureThrowsNothing)
{
  const fem::Failure none = fem::first_failure(MPI_COMM_WORLD, fem::Failure());
  EXPECT_FALSE(none.failed());
  EXPECT_NO_THROW(none.rethrow());
}

TEST(ParallelErrors, InputErrorOfOneRankIsThrownOnEveryRank)
{
  const fem::Failure local = fem::catch_failure(
      []()
      {
        if (rank() == 1)
          throw InputError("Stiffness/pinion torque", "too large");
      });
  try
  {
    fem::first_failure(MPI_COMM_WORLD, local).rethrow("position 2: ");
    FAIL() << "no exception on rank " << rank();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "Stiffness/pinion torque");
    EXPECT_EQ(e.reason(), "position 2: too large");
  }
}

TEST(ParallelErrors, FirstFailureByOrderWinsAndKeepsItsType)
{
  // Rank 0 fails at order 5 with an InputError, rank 1 at order 2 with a SolverFailure.
  const fem::Failure local =
      rank() == 0 ? fem::catch_failure([]() { throw InputError("a", "later"); })
                  : fem::catch_failure([]() { throw SolverFailure("contact", "cycling"); });
  const fem::Failure first = fem::first_failure(MPI_COMM_WORLD, local, rank() == 0 ? 5 : 2);
  EXPECT_EQ(first.kind, fem::Failure::solver);
  EXPECT_THROW(first.rethrow(), SolverFailure);
  EXPECT_EQ(first.name, "contact");
  EXPECT_EQ(first.reason, "cycling");
}

TEST(ParallelErrors, RunOnRootBroadcastsEveryFieldOfAResult)
{
  const stiffness::GearMeshStiffnessResult r =
      fem::run_on_root(MPI_COMM_WORLD,
                       []()
                       {
                         stiffness::GearMeshStiffnessResult result;
                         result.mesh_stiffness = 3.5e8;
                         result.total_time = 1.25;
                         result.n_dofs = 53000;
                         result.output_files = {"a.vtu", "b.vtu"};
                         stiffness::ToothPairLoad load;
                         load.pair = -1;
                         load.load_share = 0.375;
                         load.closed_nodes = 7;
                         result.pairs = {load, load};
                         return result;
                       });
  EXPECT_EQ(r.mesh_stiffness, 3.5e8);
  EXPECT_EQ(r.total_time, 1.25);
  EXPECT_EQ(r.n_dofs, 53000u);
  ASSERT_EQ(r.output_files.size(), 2u);
  EXPECT_EQ(r.output_files[1], "b.vtu");
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[1].pair, -1);
  EXPECT_EQ(r.pairs[1].load_share, 0.375);
  EXPECT_EQ(r.pairs[1].closed_nodes, 7u);
}

TEST(ParallelErrors, RunOnRootThrowsRootsFailureEverywhere)
{
  EXPECT_THROW(fem::run_on_root(MPI_COMM_WORLD,
                                []() -> std::vector<double>
                                { throw SolverFailure("gmsh", "no cells"); }),
               SolverFailure);
}

TEST(ParallelErrors, RefusedSweepStopsEveryRankWithTheFirstPosition)
{
  // A contact size of 1e-6 mm: every position exceeds the cell limit before meshing, so each
  // rank fails in the first round; every rank must throw position 1's InputError.
  stiffness::GearMeshStiffnessSettings settings;
  settings.scene.mesh.contact_size = 1e-9;
  stiffness::StiffnessSweepSpec spec;
  spec.positions = 4;
  try
  {
    stiffness::stiffness_sweep<2>(MPI_COMM_WORLD, settings, spec, stiffness_work_stem("refused"));
    FAIL() << "no exception on rank " << rank();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "Mesh/contact size");
    EXPECT_NE(e.reason().find("sweep position 1 "), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("cells"), std::string::npos) << e.what();
  }
}
