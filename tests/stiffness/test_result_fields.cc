// Results that cross MPI ranks list their members once (fem/fields.h): every such struct's list
// covers its whole layout (a member added without being listed fails here, by name of the
// member before the gap), and every listed member — scalars, vectors, nested structs, Eigen
// vectors — arrives on rank 0 with the value rank 1 gave it.
// Exact oracles: the values are put in on rank 1 and must come out bit-identical on rank 0.
#include "fem/fields.h"
#include "stiffness/cycloid_loads.h"
#include "stiffness/mesh_stiffness.h"

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>
#include <string>
#include <type_traits>
#include <vector>

using namespace gearstiff;

namespace
{
struct IgnoreField
{
  template <class Field>
  void operator()(const char*, Field&) const
  {
  }
};

template <class T, class = void>
struct has_fields : std::false_type
{
};
template <class T>
struct has_fields<T, std::void_t<decltype(T::for_each_field(std::declval<T&>(), IgnoreField()))>>
    : std::true_type
{
};

// A struct whose list forgets a member.
struct Partial
{
  double listed = 0.;
  double forgotten = 0.;
  unsigned int last = 0;
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("listed", self.listed);
    visit("last", self.last);
  }
};

// Gives every member of `object` (recursively, two entries per vector) a distinct value
// derived from a running counter; the same counter sequence reproduces the same object.
template <class T>
void fill(T& object, double& counter)
{
  if constexpr (has_fields<T>::value)
    T::for_each_field(object, [&counter](const char*, auto& field) { fill(field, counter); });
  else if constexpr (fem::is_fixed_size_matrix<T>::value)
    for (int i = 0; i < object.size(); ++i)
      object.data()[i] = (counter += 1.) + 0.25;
  else if constexpr (std::is_same_v<T, std::string>)
    object = "text " + std::to_string(counter += 1.);
  else if constexpr (std::is_same_v<T, bool>)
    object = static_cast<int>(counter += 1.) % 2 == 1;
  else if constexpr (std::is_arithmetic_v<T>)
    object = static_cast<T>((counter += 1.) + (std::is_floating_point_v<T> ? 0.5 : 0.));
  else // std::vector
  {
    object.resize(2);
    for (auto& element : object)
      fill(element, counter);
  }
}

// Compares member by member; `where` names the member path in a failure.
template <class T>
void expect_equal(const T& expected, const T& actual, const std::string& where)
{
  if constexpr (has_fields<T>::value)
  {
    std::vector<std::string> names;
    T::for_each_field(expected, [&names](const char* name, const auto&) { names.push_back(name); });
    std::size_t i = 0;
    std::vector<const void*> actual_fields;
    T::for_each_field(actual,
                      [&](const char*, const auto& field) { actual_fields.push_back(&field); });
    T::for_each_field(expected,
                      [&](const char*, const auto& field)
                      {
                        using Field = std::decay_t<decltype(field)>;
                        expect_equal(field, *static_cast<const Field*>(actual_fields[i]),
                                     where + "." + names[i]);
                        ++i;
                      });
  }
  else if constexpr (fem::is_fixed_size_matrix<T>::value)
    EXPECT_TRUE(expected == actual) << where;
  else if constexpr (std::is_same_v<T, std::string> || std::is_arithmetic_v<T>)
    EXPECT_EQ(expected, actual) << where;
  else
  {
    ASSERT_EQ(expected.size(), actual.size()) << where;
    for (std::size_t k = 0; k < expected.size(); ++k)
      expect_equal(expected[k], actual[k], where + "[" + std::to_string(k) + "]");
  }
}

template <class T>
void expect_every_field_reaches_rank_zero(const std::string& name)
{
  T expected;
  double counter = 0.;
  fill(expected, counter);
  T sent; // default on rank 0: only the transfer can make it equal
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 1)
    sent = expected;
  const std::vector<T> gathered = dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, sent);
  ASSERT_EQ(gathered.size(), 2u);
  expect_equal(expected, gathered[1], name);
}
} // namespace

TEST(ResultFields, EveryMemberIsListed)
{
  EXPECT_EQ(fem::field_layout_gap<stiffness::ToothPairLoad>(), "");
  EXPECT_EQ(fem::field_layout_gap<stiffness::FaceLoadPoint>(), "");
  EXPECT_EQ(fem::field_layout_gap<stiffness::GearMeshStiffnessResult>(), "");
  EXPECT_EQ(fem::field_layout_gap<stiffness::CycloidContactLoad>(), "");
  EXPECT_EQ(fem::field_layout_gap<stiffness::CycloidLoadResult>(), "");
  EXPECT_EQ(fem::field_layout_gap<stiffness::CycloidAnalyticResult>(), "");
}

TEST(ResultFields, TheLayoutCheckFindsAnUnlistedMember)
{
  EXPECT_EQ(fem::field_layout_gap<Partial>(), "after listed");
}

TEST(ResultFields, EveryMemberReachesRankZero)
{
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 2)
    GTEST_SKIP() << "needs 2 ranks";
  expect_every_field_reaches_rank_zero<stiffness::GearMeshStiffnessResult>("gear result");
  expect_every_field_reaches_rank_zero<stiffness::CycloidLoadResult>("cycloid result");
}
