// One list of a result struct's members, used for everything that must see every member:
// serialisation across MPI ranks (fem/parallel.h sends results with boost archives), and the
// check that the list is complete. A struct lists its members once, in declaration order:
//
//   struct Result
//   {
//     double k = 0.;                 // N/m
//     std::vector<Pair> pairs;
//     template <class Self, class Visit>
//     static void for_each_field(Self& self, Visit&& visit)
//     {
//       visit("k", self.k);
//       visit("pairs", self.pairs);
//     }
//     template <class Archive>
//     void serialize(Archive& archive, const unsigned int) { fem::serialize_fields(archive, *this);
//     }
//   };
//
// A member added to the struct but not to the list would silently not reach rank 0; the
// layout check (field_layout_gap) finds it: the listed members must tile the object from byte
// 0 to sizeof(T) with only alignment padding between them, so an unlisted member shows as a gap
// (tests/stiffness/test_result_fields.cc runs it for every result that crosses ranks). Header
// only (boost, no deal.II). Fixed-size Eigen vectors and matrices are listed as one member and
// sent as their coefficient array.
#pragma once

#include <algorithm>
#include <boost/serialization/array_wrapper.hpp>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace gearstiff::fem
{
// Eigen's fixed-size types (Eigen::Vector2d, ...) without including Eigen.
template <class T, class = void>
struct is_fixed_size_matrix : std::false_type
{
};
template <class T>
struct is_fixed_size_matrix<T, std::enable_if_t<(T::SizeAtCompileTime > 0)>> : std::true_type
{
};

// Serialises every listed member of `object` (boost-style archive: `archive & member`).
template <class Archive, class T>
void serialize_fields(Archive& archive, T& object)
{
  T::for_each_field(object,
                    [&archive](const char* /*name*/, auto& field)
                    {
                      using Field = std::remove_reference_t<decltype(field)>;
                      if constexpr (is_fixed_size_matrix<Field>::value)
                        archive& boost::serialization::make_array(field.data(), field.size());
                      else
                        archive& field;
                    });
}

// Names of the listed members, in list order.
template <class T>
std::vector<std::string> field_names()
{
  T object{};
  std::vector<std::string> names;
  T::for_each_field(object, [&names](const char* name, auto&) { names.emplace_back(name); });
  return names;
}

// Empty when the listed members of T cover its whole layout; otherwise where the first gap is
// ("after <member>": an unlisted member, or a member listed twice or out of place).
template <class T>
std::string field_layout_gap()
{
  struct Extent
  {
    std::size_t begin, size, alignment;
    std::string name;
  };
  T object{};
  const auto* base = reinterpret_cast<const char*>(&object);
  std::vector<Extent> extents;
  T::for_each_field(object,
                    [&](const char* name, auto& field)
                    {
                      using Field = std::remove_reference_t<decltype(field)>;
                      extents.push_back(
                          {static_cast<std::size_t>(reinterpret_cast<const char*>(&field) - base),
                           sizeof(Field), alignof(Field), name});
                    });
  std::sort(extents.begin(), extents.end(),
            [](const Extent& a, const Extent& b) { return a.begin < b.begin; });
  const auto align_up = [](std::size_t offset, std::size_t alignment)
  { return (offset + alignment - 1) / alignment * alignment; };
  std::size_t end = 0;
  std::string previous = "the start";
  for (const Extent& e : extents)
  {
    if (e.begin != align_up(end, e.alignment))
      return "after " + previous;
    end = e.begin + e.size;
    previous = e.name;
  }
  if (align_up(end, alignof(T)) != sizeof(T))
    return "after " + previous;
  return {};
}
} // namespace gearstiff::fem
