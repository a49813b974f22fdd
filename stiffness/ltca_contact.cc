#include "stiffness/ltca_contact.h"

#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace gearstiff::stiffness
{
double hertz_layer_compression(double peak_pressure, double half_width, const LayerBody& body)
{
  // On the axis (Johnson 1985 §2.6): σ_z = −p0·a/√(a²+z²), σ_x = −(p0/a)·((a²+2z²)/√(a²+z²) − 2z);
  // plane strain ε_z = [(1−ν²)σ_z − ν(1+ν)σ_x]/E. The integrals over 0..h are closed forms:
  // ∫σ_z = −p0·a·asinh(h/a), ∫σ_x = −(p0/a)·(h·√(a²+h²) − h²).
  const double a = half_width, h = body.matching_depth, nu = body.poisson_ratio;
  const double sigma_z = peak_pressure * a * std::asinh(h / a);
  const double sigma_x = peak_pressure / a * (h * std::sqrt(a * a + h * h) - h * h);
  return body.wedge_factor * ((1. - nu * nu) * sigma_z - nu * (1. + nu) * sigma_x) /
         body.young_modulus;
}

namespace
{
// −[(1−ν²)·ln(1 + ξ²/h²) + (1+ν)·ξ²/(ξ²+h²)]/(πE) and its integral in ξ.
double depth_shift_kernel(double xi, const LayerBody& body)
{
  const double h = body.matching_depth, nu = body.poisson_ratio;
  const double c = 1. - nu * nu;
  const double q = xi * xi / (h * h);
  return -(c * std::log1p(q) + (1. + nu) * q / (1. + q)) / (M_PI * body.young_modulus);
}
double depth_shift_integral(double xi, const LayerBody& body)
{
  const double h = body.matching_depth, nu = body.poisson_ratio;
  const double c = 1. - nu * nu;
  const double atan = std::atan(xi / h);
  return -(c * (xi * std::log1p(xi * xi / (h * h)) - 2. * xi + 2. * h * atan) +
           (1. + nu) * (xi - h * atan)) /
         (M_PI * body.young_modulus);
}
} // namespace

double spread_load_depth_shift(double line_load, double half_width, const LayerBody& body)
{
  // The mean of the kernel over the elliptic pressure, ξ = a·cos θ: Gauss–Chebyshev of the
  // second kind, (2/(n+1))·Σ sin²θ_i·f(a·cos θ_i), θ_i = iπ/(n+1); the kernel is smooth on
  // |ξ| ≤ a, 32 points are exact to round-off for a/h ≤ 1.
  constexpr int n = 32;
  double mean = 0.;
  for (int i = 1; i <= n; ++i)
  {
    const double theta = i * M_PI / (n + 1);
    mean +=
        std::sin(theta) * std::sin(theta) * depth_shift_kernel(half_width * std::cos(theta), body);
  }
  return line_load * 2. / (n + 1) * mean;
}

double spread_load_depth_cell(double from, double to, const LayerBody& body)
{
  return depth_shift_integral(to, body) - depth_shift_integral(from, body);
}

double tip_edge_wedge_factor(double tip_pressure_angle)
{
  const double alpha = 0.5 * (0.5 * M_PI + tip_pressure_angle); // half the corner's angle
  const double beta = 0.5 * M_PI - alpha;                       // the load off the bisector
  const double c = std::cos(beta), s = std::sin(beta);
  return 0.5 * M_PI *
         (c * c / (alpha + 0.5 * std::sin(2. * alpha)) +
          s * s / (alpha - 0.5 * std::sin(2. * alpha)));
}

namespace
{
// Ĝ(s, α) of corner_layer_excess: the FE wedge's layer excess over (f − 1)·2(1−ν²)/(πE) at
// s = distance/h (a load of width 0.1·distance at that distance from the apex, read under it),
// tools/wedge_layer.py, 2026-12-05.
constexpr std::array<double, 9> corner_s = {{0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6}};
constexpr std::array<double, 5> corner_alpha = {{10., 17.5, 25., 32., 40.}}; // degrees
constexpr std::array<std::array<double, 9>, 5> corner_g = {{
    {{3.5659, 2.8876, 2.2236, 1.3947, 0.8486, 0.4418, 0.2217, 0.1190, 0.0608}},
    {{3.4910, 2.8154, 2.1569, 1.3437, 0.8204, 0.4432, 0.2406, 0.1359, 0.0714}},
    {{3.4036, 2.7316, 2.0802, 1.2869, 0.7906, 0.4454, 0.2607, 0.1550, 0.0836}},
    {{3.3073, 2.6399, 1.9972, 1.2274, 0.7606, 0.4482, 0.2818, 0.1759, 0.0975}},
    {{3.1731, 2.5129, 1.8839, 1.1484, 0.7219, 0.4519, 0.3099, 0.2052, 0.1172}},
}};

// Ĝ at one tabulated angle: linear in ln s; below the table the wedge's log, ln(s₀/s) more (the
// FE's step from 0.005 to 0.01 is 0.98·ln 2); above it the 1/s decay of the far field (its
// last step 0.51–0.53 of the value per doubling).
double corner_g_at(std::size_t angle, double s)
{
  const auto& g = corner_g[angle];
  if (s <= corner_s.front())
    return g.front() + std::log(corner_s.front() / s);
  if (s >= corner_s.back())
    return g.back() * corner_s.back() / s;
  const std::size_t i =
      std::upper_bound(corner_s.begin(), corner_s.end(), s) - corner_s.begin() - 1;
  const double t = std::log(s / corner_s[i]) / std::log(corner_s[i + 1] / corner_s[i]);
  return (1. - t) * g[i] + t * g[i + 1];
}
} // namespace

namespace
{
// A body's corner once: its angle's place in the table and the factor (f − 1)·2(1−ν²)/(πE).
struct CornerScale
{
  std::size_t angle = 0; // the tabulated angle below α_tip
  double weight = 0.;    // -, linear between it and the next
  double factor = 0.;    // m per N/m
};

CornerScale corner_scale(const LayerBody& body)
{
  // Linear in α between the tabulated angles, held at the table's ends (a tip's pressure angle
  // below 10° or above 40°: Ĝ moves by 4 % over 10 … 40° where (f − 1) does most).
  const double degrees = std::clamp(body.corner_pressure_angle * 180. / M_PI, corner_alpha.front(),
                                    corner_alpha.back());
  CornerScale scale;
  scale.angle =
      std::min<std::size_t>(std::upper_bound(corner_alpha.begin(), corner_alpha.end(), degrees) -
                                corner_alpha.begin() - 1,
                            corner_alpha.size() - 2);
  scale.weight = (degrees - corner_alpha[scale.angle]) /
                 (corner_alpha[scale.angle + 1] - corner_alpha[scale.angle]);
  const double nu = body.poisson_ratio;
  scale.factor = (tip_edge_wedge_factor(body.corner_pressure_angle) - 1.) * 2. * (1. - nu * nu) /
                 (M_PI * body.young_modulus);
  return scale;
}

double corner_excess(const CornerScale& scale, double distance, double matching_depth)
{
  const double s = std::max(distance, 1e-9) / matching_depth;
  return scale.factor * ((1. - scale.weight) * corner_g_at(scale.angle, s) +
                         scale.weight * corner_g_at(scale.angle + 1, s));
}
} // namespace

double corner_layer_excess(double distance, const LayerBody& body)
{
  return corner_excess(corner_scale(body), distance, body.matching_depth);
}

namespace
{
// Ê(Δz/h, i) of end_face_layer_excess for the node planes i = 0, 1, 2 from a free end: the 3D
// Q1 quarter-space's layer compression over the plane-strain one's, in units of 2(1−ν²)/(πE)
// per N/m, a Hertzian line load of half-width 0.1·h along the whole face (tools/end_face_layer.py,
// 2026-12-05). The x–y mesh refined twice moves the end plane's entry by +0.7 %, a/h 0.05 / 0.2
// by +1.5 / −3.9 %, the far boundaries halved by −1 % (at Δz/h = 1).
constexpr std::array<double, 11> end_ratio = {{0.5, 0.75, 1., 1.5, 2., 3., 4., 6., 8., 12., 16.}};
constexpr std::array<std::array<double, 3>, 11> end_face_e = {{
    {{0.4144, 0.1406, 0.1012}},
    {{0.3415, 0.1019, 0.0734}},
    {{0.2914, 0.0801, 0.0571}},
    {{0.2260, 0.0562, 0.0389}},
    {{0.1844, 0.0433, 0.0290}},
    {{0.1344, 0.0298, 0.0188}},
    {{0.1052, 0.0227, 0.0136}},
    {{0.0727, 0.0154, 0.0086}},
    {{0.0551, 0.0116, 0.0061}},
    {{0.0365, 0.0077, 0.0036}},
    {{0.0269, 0.0057, 0.0022}},
}};
// The quarter-space's layer excess far from the end: Ê·z/h settles at 0.120 from z = 3·h (the
// FE at Δz/h 0.5: 0.1181, 0.1201, 0.1203, 0.1190 at z/h 2.5, 3.5, 4.5, 8).
constexpr double end_tail = 0.120;
constexpr double end_tail_reach = 8.; // z/h
} // namespace

double end_face_layer_excess(double spacing, double matching_depth, unsigned int plane)
{
  const double ratio = spacing / matching_depth;
  if (plane >= end_face_e.front().size())
  {
    const double z = plane * ratio;
    return z <= end_tail_reach ? end_tail / z : 0.;
  }
  // Finer layers than the table: its first row (the continuum's end plane grows as ln(h/a),
  // beyond what a node plane of the exact path resolves); coarser: the 1/ratio decay of its
  // last steps (Ê·ratio 0.441, 0.438, 0.430 at 8, 12, 16).
  if (ratio <= end_ratio.front())
    return end_face_e.front()[plane];
  if (ratio >= end_ratio.back())
    return end_face_e.back()[plane] * end_ratio.back() / ratio;
  const std::size_t i =
      std::upper_bound(end_ratio.begin(), end_ratio.end(), ratio) - end_ratio.begin() - 1;
  const double t = std::log(ratio / end_ratio[i]) / std::log(end_ratio[i + 1] / end_ratio[i]);
  return (1. - t) * end_face_e[i][plane] + t * end_face_e[i + 1][plane];
}

namespace
{
// K(Δz/h) of layer_kernel_departure: per Δz/h of kernel_ratio, the interior row (the
// compression at the loaded plane and the next kernel_reach over plane strain) and the rows of
// the planes loaded 0 … 4 from a free end (the compression at planes 0 … loaded + kernel_reach),
// a Hertzian line load of half-width 0.1·h on one node plane alone, its nodal force w·Δz
// (tools/end_face_layer.py --rows, 2026-12-07). Consistent with end_face_e measured
// independently under a uniform load: summed over the loaded planes of a long face at Δz/h 2,
// 2.77·Σ(K − I) at the planes 0, 1, 2 from the end is 0.1909, 0.0449, 0.0300 against Ê 0.1844,
// 0.0433, 0.0290 (test_influence_coefficients, LayerKernel). Ê stays on the diagonal beside
// the kernel all the same: the end plane needs it twice, measured, not derived (docs/ltca.md §3
// "End faces").
constexpr std::array<double, 6> kernel_ratio = {{0.5, 1., 2., 4., 8., 16.}};
constexpr unsigned int kernel_reach = 7;
using KernelRows = std::array<std::array<double, layer_kernel_end_planes + kernel_reach>,
                              1 + layer_kernel_end_planes>;
constexpr std::array<KernelRows, 6> kernel_rows = {{
    // clang-format off
    // Δz/h 0.5: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.2595, -0.1488, 0.0286, -0.0077, -0.0001, -0.0009, -0.0004, -0.0003}},
      {{1.4735, -0.1802, 0.0399, -0.0031, 0.0048, 0.0026, 0.0023, 0.0019}},
      {{-0.3597, 1.3588, -0.1490, 0.0392, -0.0024, 0.0046, 0.0027, 0.0026, 0.0022}},
      {{0.0661, -0.1507, 1.2713, -0.1444, 0.0327, -0.0046, 0.0025, 0.0013, 0.0015, 0.0013}},
      {{-0.0197, 0.0352, -0.1458, 1.2628, -0.1464, 0.0307, -0.0059, 0.0015, 0.0005, 0.0008, 0.0008}},
      {{-0.0009, -0.0070, 0.0307, -0.1471, 1.2611, -0.1474, 0.0299, -0.0065, 0.0010, 0.0000, 0.0005, 0.0005}},
    }},
    // Δz/h 1: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.5052, -0.2955, 0.0536, -0.0128, 0.0022, -0.0008, 0.0000, -0.0001}},
      {{1.6736, -0.3211, 0.0706, -0.0090, 0.0059, 0.0015, 0.0017, 0.0012}},
      {{-0.6579, 1.6184, -0.3104, 0.0632, -0.0101, 0.0053, 0.0014, 0.0018, 0.0014}},
      {{0.1186, -0.3126, 1.5139, -0.2944, 0.0560, -0.0111, 0.0037, 0.0004, 0.0011, 0.0008}},
      {{-0.0292, 0.0585, -0.2955, 1.5068, -0.2944, 0.0547, -0.0118, 0.0031, -0.0000, 0.0007, 0.0005}},
      {{0.0044, -0.0138, 0.0543, -0.2949, 1.5059, -0.2948, 0.0542, -0.0122, 0.0028, -0.0003, 0.0005, 0.0003}},
    }},
    // Δz/h 2: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.6497, -0.3979, 0.0890, -0.0204, 0.0046, -0.0010, 0.0003, 0.0000}},
      {{1.7644, -0.4085, 0.1021, -0.0191, 0.0069, 0.0001, 0.0012, 0.0006}},
      {{-0.8484, 1.7735, -0.4234, 0.0989, -0.0200, 0.0066, 0.0000, 0.0013, 0.0008}},
      {{0.1882, -0.4259, 1.6584, -0.3985, 0.0905, -0.0196, 0.0054, -0.0004, 0.0009, 0.0005}},
      {{-0.0440, 0.0954, -0.3993, 1.6507, -0.3974, 0.0896, -0.0199, 0.0051, -0.0007, 0.0006, 0.0003}},
      {{0.0093, -0.0222, 0.0895, -0.3977, 1.6500, -0.3976, 0.0893, -0.0201, 0.0049, -0.0008, 0.0005, 0.0002}},
    }},
    // Δz/h 4: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.7114, -0.4467, 0.1128, -0.0279, 0.0071, -0.0016, 0.0005, -0.0000}},
      {{1.7811, -0.4472, 0.1190, -0.0273, 0.0083, -0.0011, 0.0009, 0.0002}},
      {{-0.9288, 1.8384, -0.4770, 0.1226, -0.0289, 0.0083, -0.0012, 0.0010, 0.0003}},
      {{0.2326, -0.4796, 1.7205, -0.4484, 0.1139, -0.0276, 0.0074, -0.0013, 0.0007, 0.0001}},
      {{-0.0582, 0.1208, -0.4488, 1.7122, -0.4466, 0.1130, -0.0277, 0.0072, -0.0015, 0.0006, 0.0001}},
      {{0.0141, -0.0301, 0.1133, -0.4468, 1.7115, -0.4466, 0.1129, -0.0278, 0.0071, -0.0015, 0.0006, 0.0000}},
    }},
    // Δz/h 8: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.7304, -0.4629, 0.1229, -0.0319, 0.0085, -0.0021, 0.0006, -0.0002}},
      {{1.7692, -0.4602, 0.1248, -0.0314, 0.0089, -0.0019, 0.0007, -0.0001}},
      {{-0.9475, 1.8569, -0.4951, 0.1323, -0.0338, 0.0093, -0.0021, 0.0007, -0.0001}},
      {{0.2499, -0.4971, 1.7395, -0.4651, 0.1237, -0.0320, 0.0086, -0.0021, 0.0006, -0.0001}},
      {{-0.0654, 0.1317, -0.4654, 1.7310, -0.4631, 0.1230, -0.0319, 0.0085, -0.0021, 0.0006, -0.0001}},
      {{0.0170, -0.0343, 0.1235, -0.4631, 1.7304, -0.4629, 0.1229, -0.0319, 0.0085, -0.0021, 0.0006, -0.0002}},
    }},
    // Δz/h 16: interior; loaded on plane 0, 1, 2, 3, 4 from the end
    {{
      {{1.7337, -0.4659, 0.1255, -0.0335, 0.0089, -0.0024, 0.0006, -0.0002}},
      {{1.7537, -0.4633, 0.1257, -0.0332, 0.0090, -0.0023, 0.0006, -0.0002}},
      {{-0.9443, 1.8591, -0.4988, 0.1345, -0.0358, 0.0095, -0.0026, 0.0007, -0.0002}},
      {{0.2536, -0.5000, 1.7427, -0.4683, 0.1262, -0.0336, 0.0089, -0.0024, 0.0006, -0.0002}},
      {{-0.0676, 0.1346, -0.4683, 1.7344, -0.4661, 0.1256, -0.0335, 0.0089, -0.0024, 0.0006, -0.0002}},
      {{0.0180, -0.0359, 0.1262, -0.4661, 1.7338, -0.4659, 0.1255, -0.0335, 0.0089, -0.0024, 0.0006, -0.0002}},
    }},
    // clang-format on
}};

// K(read, loaded) − δ at the table's row r: the interior row, and each end's own rows where the
// loaded plane lies within layer_kernel_end_planes of it, as their departure from the interior
// row (a narrow face's middle planes feel both ends).
double kernel_entry(std::size_t r, unsigned int planes, unsigned int read, unsigned int loaded)
{
  const KernelRows& rows = kernel_rows[r];
  const unsigned int distance = read > loaded ? read - loaded : loaded - read;
  const auto interior = [&](unsigned int d) { return d <= kernel_reach ? rows[0][d] : 0.; };
  double k = interior(distance);
  for (const bool far_end : {false, true})
  {
    const unsigned int from_end = far_end ? planes - 1 - loaded : loaded;
    const unsigned int read_from_end = far_end ? planes - 1 - read : read;
    if (from_end < layer_kernel_end_planes && read_from_end <= from_end + kernel_reach)
      k += rows[1 + from_end][read_from_end] - interior(distance);
  }
  return k - (read == loaded ? 1. : 0.);
}
} // namespace

double layer_kernel_departure(double spacing, double matching_depth, unsigned int planes,
                              unsigned int read, unsigned int loaded)
{
  const double ratio =
      std::clamp(spacing / matching_depth, kernel_ratio.front(), kernel_ratio.back());
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(kernel_ratio.begin(), kernel_ratio.end(), ratio) - kernel_ratio.begin() - 1,
      kernel_ratio.size() - 2);
  const double t =
      std::log(ratio / kernel_ratio[i]) / std::log(kernel_ratio[i + 1] / kernel_ratio[i]);
  return (1. - t) * kernel_entry(i, planes, read, loaded) +
         t * kernel_entry(i + 1, planes, read, loaded);
}

namespace
{
// The corner's excess under a Hertzian line load w of half-width a centred at the contact: the
// mean of corner_layer_excess over the elliptic pressure (Gauss–Chebyshev, as
// spread_load_depth_shift), each part at its own distance from the corner; 0 without a corner.
double corner_shift(double line_load, double half_width, const LayerBody& body)
{
  if (std::isnan(body.corner_offset))
    return 0.;
  // Far from the corner the excess is smooth over the zone: its mean is its value at the centre
  // within (a/d)²/8 of its curvature, < 1 % of a small excess beyond 8·a (a contact's own table
  // lookups are then one, not 32: 31 → 12 µs a Hertz call, measured 2026-12-05). Between 6·a
  // and 8·a the two are blended (smoothstep in d/a): a switch made δ(F) jump by that < 1 %
  // where a growing zone passed 8·a — 5·10⁻¹¹ m on an own internal helical pair with rounded
  // tips, where Newton's method then failed (test_influence_coefficients
  // NewtonAcrossCornerSwitch).
  const CornerScale scale = corner_scale(body);
  const double distance = std::abs(body.corner_offset);
  if (distance >= 8. * half_width)
    return line_load * corner_excess(scale, distance, body.matching_depth);
  constexpr int n = 32;
  double mean = 0.;
  for (int i = 1; i <= n; ++i)
  {
    const double theta = i * M_PI / (n + 1);
    mean += std::sin(theta) * std::sin(theta) *
            corner_excess(scale, std::abs(half_width * std::cos(theta) - body.corner_offset),
                          body.matching_depth);
  }
  mean *= 2. / (n + 1);
  if (distance <= 6. * half_width)
    return line_load * mean;
  const double t = (distance / half_width - 6.) / 2.;
  const double blend = t * t * (3. - 2. * t);
  const double centre = corner_excess(scale, distance, body.matching_depth);
  return line_load * ((1. - blend) * mean + blend * centre);
}

// Half-width and peak pressure of the Hertz line contact (Johnson 1985 §4.3).
std::pair<double, double> hertz_zone(double force, double face_width, double relative_radius,
                                     const LayerBody& first, const LayerBody& second)
{
  const double e_star =
      1. / ((1. - first.poisson_ratio * first.poisson_ratio) / first.young_modulus +
            (1. - second.poisson_ratio * second.poisson_ratio) / second.young_modulus);
  const double line_load = force / face_width;
  const double a = std::sqrt(4. * line_load * relative_radius / (M_PI * e_star));
  return {a, 2. * line_load / (M_PI * a)};
}

double layer_approach(double force, double face_width, double relative_radius,
                      const LayerBody& first, const LayerBody& second)
{
  const auto [a, p0] = hertz_zone(force, face_width, relative_radius, first, second);
  const double line_load = force / face_width;
  return hertz_layer_compression(p0, a, first) + hertz_layer_compression(p0, a, second) +
         spread_load_depth_shift(line_load, a, first) +
         spread_load_depth_shift(line_load, a, second) + corner_shift(line_load, a, first) +
         corner_shift(line_load, a, second);
}
} // namespace

LineContact hertz_line_contact(double force, double face_width, double relative_radius,
                               const LayerBody& first, const LayerBody& second)
{
  LineContact contact;
  if (!(force > 0.))
    return contact;
  std::tie(contact.half_width, contact.peak_pressure) =
      hertz_zone(force, face_width, relative_radius, first, second);
  contact.approach = layer_approach(force, face_width, relative_radius, first, second);
  // δ ≈ c·F·(ln(K/F)): smooth for F > 0; a central difference of relative step 1e-6 is exact
  // to ~1e-10 of dδ/dF, far below what the Newton iteration needs.
  const double step = 1e-6 * force;
  contact.compliance = (layer_approach(force + step, face_width, relative_radius, first, second) -
                        layer_approach(force - step, face_width, relative_radius, first, second)) /
                       (2. * step);
  return contact;
}

namespace
{
// The two parts of the cell integral of the Flamant kernel (half_plane_cell_displacement): the
// part in ξ alone, Q(ξ) = ∫[(1−ν²)·ln(ξ²+h²) − (1+ν)·h²/(ξ²+h²)]dξ, and the part in t = ξ − x,
// R(t) = ∫−2(1−ν²)·ln|t| dt; both over πE.
double flamant_depth_part(double xi, const LayerBody& body)
{
  const double h = body.matching_depth, nu = body.poisson_ratio;
  const double atan = std::atan(xi / h);
  return ((1. - nu * nu) * (xi * std::log(xi * xi + h * h) - 2. * xi + 2. * h * atan) -
          (1. + nu) * h * atan) /
         (M_PI * body.young_modulus);
}

double flamant_surface_part(double t, const LayerBody& body)
{
  const double nu = body.poisson_ratio;
  const double t_log_t = t == 0. ? 0. : t * std::log(std::abs(t));
  return -2. * (1. - nu * nu) * (t_log_t - t) / (M_PI * body.young_modulus);
}
} // namespace

double half_plane_cell_displacement(double x, double from, double to, const LayerBody& body)
{
  // u_z(x, 0) − u_z(0, h) of a line load at ξ: the surface's −(2(1−ν²)/(πE))·ln|x−ξ| relative
  // to the surface under 0, plus the compression of the axis 0 ≤ z ≤ h under the offset load
  // (Flamant's σ_r = −(2P/π)·cos θ/r on the axis at (−ξ, z), integrated in closed form).
  return flamant_depth_part(to, body) - flamant_depth_part(from, body) +
         flamant_surface_part(to - x, body) - flamant_surface_part(from - x, body);
}

namespace
{
// The strip's influence matrix (m/Pa), both bodies: cell k's unit pressure at cell i's centre.
// Cell edges ξ_k = −L + k·Δ and centres x_i = −L + (i + ½)·Δ make the surface part a function
// of k − i: 3n + 1 kernel evaluations per body instead of 2n².
Eigen::MatrixXd strip_influence(int n, double half_span, const LayerBody& first,
                                const LayerBody& second)
{
  const double cell = 2. * half_span / n;
  Eigen::MatrixXd influence(n, n);
  std::vector<double> depth_part(n + 1, 0.), surface_part(2 * n + 1, 0.);
  for (const LayerBody* body : {&first, &second})
  {
    for (int k = 0; k <= n; ++k)
      depth_part[k] += flamant_depth_part(-half_span + k * cell, *body);
    for (int m = -n; m <= n; ++m) // edge k, centre i: t = (k − i − ½)·Δ, m = k − i
      surface_part[m + n] += flamant_surface_part((m - 0.5) * cell, *body);
  }
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      influence(i, k) =
          depth_part[k + 1] - depth_part[k] + surface_part[k + 1 - i + n] - surface_part[k - i + n];
  // A body's sharp tip corner (LayerBody::corner_offset): each cell's load compresses its layer
  // by the corner's excess at the cell's distance, read as a shift of the whole strip (the
  // table's read lies under the load; its variation across the zone is not modelled).
  for (const LayerBody* body : {&first, &second})
    if (!std::isnan(body->corner_offset))
    {
      const CornerScale scale = corner_scale(*body);
      for (int k = 0; k < n; ++k)
        influence.col(k).array() +=
            cell * corner_excess(scale,
                                 std::abs(-half_span + (k + 0.5) * cell - body->corner_offset),
                                 body->matching_depth);
    }
  return influence;
}

// Pressures (Pa) of the loaded cells and the approach δ (m) for a fixed active set:
// Σ_k A_ik·p_k + g_i = δ on the active cells, Σ p_k·Δ = w.
std::pair<Eigen::VectorXd, double> strip_pressures(const Eigen::MatrixXd& influence,
                                                   const std::vector<double>& gap,
                                                   const std::vector<int>& active, double cell,
                                                   double line_load)
{
  const int m = active.size();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(m + 1, m + 1);
  Eigen::VectorXd rhs(m + 1);
  for (int a = 0; a < m; ++a)
  {
    for (int b = 0; b < m; ++b)
      system(a, b) = influence(active[a], active[b]);
    system(a, m) = -1.;
    system(m, a) = cell;
    rhs[a] = -gap[active[a]];
  }
  rhs[m] = line_load;
  const Eigen::VectorXd solution = system.partialPivLu().solve(rhs);
  return {solution.head(m), solution[m]};
}

// The strip's active set for line load w: starts from the Hertz zone around the smallest gap,
// drops cells of negative pressure, adds cells whose surface would pass the approach.
LineContact solve_strip(const Eigen::MatrixXd& influence, double line_load,
                        const ContactStrip& strip, const LayerBody& first, const LayerBody& second,
                        std::vector<double>* cell_pressure = nullptr)
{
  const int n = strip.gap.size();
  const double cell = 2. * strip.half_span / n;
  const double e_star =
      1. / ((1. - first.poisson_ratio * first.poisson_ratio) / first.young_modulus +
            (1. - second.poisson_ratio * second.poisson_ratio) / second.young_modulus);
  const double hertz_a = std::sqrt(4. * line_load * strip.relative_radius / (M_PI * e_star));
  const double smallest = *std::min_element(strip.gap.begin(), strip.gap.end());
  std::vector<char> loaded(n, 0);
  for (int i = 0; i < n; ++i)
    loaded[i] = strip.gap[i] <= smallest + 0.5 * hertz_a * hertz_a / strip.relative_radius;
  for (int pass = 0; pass < 4 * n; ++pass)
  {
    std::vector<int> active;
    for (int i = 0; i < n; ++i)
      if (loaded[i])
        active.push_back(i);
    const auto [pressure, approach] =
        strip_pressures(influence, strip.gap, active, cell, line_load);
    bool changed = false;
    for (std::size_t a = 0; a < active.size(); ++a)
      if (pressure[a] < 0.)
        loaded[active[a]] = 0, changed = true;
    if (changed)
      continue;
    Eigen::VectorXd full = Eigen::VectorXd::Zero(n);
    for (std::size_t a = 0; a < active.size(); ++a)
      full[active[a]] = pressure[a];
    const Eigen::VectorXd surface = influence * full;
    // 1e-15 m: round-off of the µm-sized displacements.
    for (int i = 0; i < n; ++i)
      if (!loaded[i] && strip.gap[i] + surface[i] < approach - 1e-15)
        loaded[i] = 1, changed = true;
    if (changed)
      continue;
    if (loaded.front() || loaded.back())
      throw SolverFailure("influence-coefficient contact",
                          "the contact zone of a modified flank reached the end of its strip");
    LineContact contact;
    contact.approach = approach;
    // The depth point under the strip's centre moves less under the spread load than under its
    // resultant there (spread_load_depth_shift), as the Hertz layer's.
    for (const int i : active)
      for (const LayerBody* body : {&first, &second})
        contact.approach +=
            full[i] * spread_load_depth_cell(-strip.half_span + i * cell,
                                             -strip.half_span + (i + 1) * cell, *body);
    Eigen::Index peak = 0;
    contact.peak_pressure = full.maxCoeff(&peak);
    contact.peak_offset = -strip.half_span + (static_cast<double>(peak) + 0.5) * cell;
    contact.half_width = 0.5 * cell * (active.back() - active.front() + 1);
    if (cell_pressure != nullptr)
      cell_pressure->assign(full.data(), full.data() + n);
    return contact;
  }
  throw SolverFailure("influence-coefficient contact",
                      "the contact zone of a modified flank did not settle");
}
} // namespace

LineContact strip_line_contact(double force, double face_width, const ContactStrip& strip,
                               const LayerBody& first, const LayerBody& second)
{
  if (!(force > 0.))
    return {};
  const Eigen::MatrixXd influence =
      strip_influence(strip.gap.size(), strip.half_span, first, second);
  LineContact contact = solve_strip(influence, force / face_width, strip, first, second);
  // δ(F) is piecewise affine (affine while the loaded cells stay): a central difference of
  // relative step 1e-6 is exact within a piece, good enough for Newton across pieces.
  const double step = 1e-6 * force;
  contact.compliance =
      (solve_strip(influence, (force + step) / face_width, strip, first, second).approach -
       solve_strip(influence, (force - step) / face_width, strip, first, second).approach) /
      (2. * step);
  return contact;
}

std::vector<double> strip_cell_pressures(double force, double face_width, const ContactStrip& strip,
                                         const LayerBody& first, const LayerBody& second)
{
  std::vector<double> pressure(strip.gap.size(), 0.);
  if (force > 0.)
    solve_strip(strip_influence(strip.gap.size(), strip.half_span, first, second),
                force / face_width, strip, first, second, &pressure);
  return pressure;
}

namespace
{
// Pair j's near field: the strip where its gap is not a Hertz parabola, else Hertz.
LineContact near_field(const MeshContactProblem& problem, int j, double force)
{
  const double width = problem.width.empty() ? problem.face_width : problem.width[j];
  LayerBody pinion = problem.pinion, wheel = problem.wheel;
  if (j < static_cast<int>(problem.pinion_corner.size()))
  {
    pinion.corner_offset = problem.pinion_corner[j];
    wheel.corner_offset = problem.wheel_corner[j];
  }
  if (j < static_cast<int>(problem.pinion_wedge.size()))
  {
    pinion.wedge_factor = problem.pinion_wedge[j];
    wheel.wedge_factor = problem.wheel_wedge[j];
  }
  LineContact contact =
      j < static_cast<int>(problem.strip.size()) && !problem.strip[j].gap.empty()
          ? strip_line_contact(force, width, problem.strip[j], pinion, wheel)
          : hertz_line_contact(force, width, problem.relative_radius[j], pinion, wheel);
  // Near an end face the layer is softer by an amount linear in the line load
  // (end_face_layer_excess): a shift of the whole zone, its pressure unchanged.
  if (j < static_cast<int>(problem.end_excess.size()) && problem.end_excess[j] != 0. && force > 0.)
  {
    const auto unit = [](const LayerBody& body)
    { return 2. * (1. - body.poisson_ratio * body.poisson_ratio) / (M_PI * body.young_modulus); };
    const double excess = problem.end_excess[j] * (unit(pinion) + unit(wheel)) / width;
    contact.approach += excess * force;
    contact.compliance += excess;
  }
  return contact;
}

double lever(const MeshContactProblem& problem, int j)
{
  return problem.lever_ratio.empty() ? 1. : problem.lever_ratio[j];
}

// Newton on the active pairs for F (≥ 0) and e: Σ_k C_jk F_k + δ(F_j) − λ_j·(e − s_j) = 0 on
// the active set, Σ λ_j·F_j = W, the friction forces `friction` (N, may be empty) held: their
// gaps Σ_k G_jk f_k and their torque Σ_k a_k f_k (MeshContactProblem). Steps are damped to keep
// every force positive (δ is defined for F > 0); a force driven below 1e-12·W leaves the active set
// (returned false with it cleared).
bool newton_on_active(const MeshContactProblem& problem, const std::vector<int>& active,
                      const std::vector<double>& friction, std::vector<double>& force,
                      double& approach, unsigned int& steps)
{
  const int n = active.size();
  double friction_torque = 0.; // N: Σ a_k f_k, the torque the friction forces carry over r_b1
  for (std::size_t k = 0; k < friction.size(); ++k)
    friction_torque += problem.friction_arm[k] * friction[k];
  for (unsigned int iteration = 0; iteration < 100; ++iteration, ++steps)
  {
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n + 1, n + 1);
    Eigen::VectorXd residual(n + 1);
    double sum = 0.;
    for (int a = 0; a < n; ++a)
    {
      const int j = active[a];
      const LineContact near = near_field(problem, j, force[j]);
      residual[a] = near.approach - lever(problem, j) * (approach - problem.separation[j]);
      for (std::size_t k = 0; k < friction.size(); ++k)
        residual[a] += problem.gap_under_friction[j][k] * friction[k];
      for (int b = 0; b < n; ++b)
      {
        residual[a] += problem.compliance[j][active[b]] * force[active[b]];
        jacobian(a, b) = problem.compliance[j][active[b]];
      }
      jacobian(a, a) += near.compliance;
      jacobian(a, n) = -lever(problem, j);
      jacobian(n, a) = lever(problem, j);
      sum += lever(problem, j) * force[j];
    }
    residual[n] = sum + friction_torque - problem.total_force;
    const Eigen::VectorXd delta = jacobian.partialPivLu().solve(-residual);
    double damping = 1.;
    for (int a = 0; a < n; ++a)
      if (delta[a] < 0.)
        damping = std::min(damping, 0.5 * force[active[a]] / -delta[a]);
    for (int a = 0; a < n; ++a)
      force[active[a]] += damping * delta[a];
    approach += damping * delta[n];
    for (int a = 0; a < n; ++a)
      if (force[active[a]] < 1e-12 * problem.total_force)
      {
        force[active[a]] = 0.;
        return false;
      }
    // 1e-12 of the load and 1e-16 m (1e-10 of a µm-sized approach): round-off level.
    const double largest = delta.head(n).cwiseAbs().maxCoeff();
    if (damping == 1. && largest < 1e-12 * problem.total_force && std::abs(delta[n]) < 1e-16)
      return true;
  }
  throw SolverFailure("influence-coefficient contact",
                      "Newton's method on the loaded pairs did not converge in 100 steps");
}

// δ_j(0+), m: where pair j's near field starts as its force rises from zero. Hertz: 0. A strip:
// its smallest cell gap, which its solution at a vanishing load takes as the approach — the cells
// sample g(c + x) − g(c) off the touching point c (c lies on a cell boundary), so it is up to
// cell²/(8R) above 0 (0.2–0.7 nm, 96 cells). Measured session 43 (the built-in pair at β ±15°,
// 6 µm tip reliefs, 13 layers, torques 12.35 … 98.8 N·m, 61.75 N·m): an unloaded pair
// penetrating by 2.36e-10 m against a strip's 6.26e-10 m entered, its force fell to zero, it
// left and entered again until the passes ran out (exit 3).
double unloaded_approach(const MeshContactProblem& problem, int j)
{
  if (j < static_cast<int>(problem.strip.size()) && !problem.strip[j].gap.empty())
    return *std::min_element(problem.strip[j].gap.begin(), problem.strip[j].gap.end());
  return 0.;
}

// The gap g_j = λ_j·(e − s_j) − Σ_k C_jk F_k − δ_j(0+) of an unloaded pair (> 0: it would
// penetrate: the smallest force it could carry would already close it).
double penetration(const MeshContactProblem& problem, const std::vector<double>& force,
                   const std::vector<double>& friction, double approach, int j)
{
  double g = lever(problem, j) * (approach - problem.separation[j]) - unloaded_approach(problem, j);
  for (std::size_t k = 0; k < force.size(); ++k)
    g -= problem.compliance[j][k] * force[k];
  for (std::size_t k = 0; k < friction.size(); ++k)
    g -= problem.gap_under_friction[j][k] * friction[k];
  return g;
}

// The normal problem with the friction forces `friction` (N, may be empty) held.
MeshContactSolution solve_normal(const MeshContactProblem& problem,
                                 const std::vector<double>& start,
                                 const std::vector<double>& friction)
{
  const int n = problem.separation.size();
  if (n == 0)
    throw SolverFailure("influence-coefficient contact", "no tooth pair in contact");
  MeshContactSolution solution;
  std::vector<double>& force = solution.force;
  // Warm start: the neighbour's forces when it had as many pairs, else the smallest gaps loaded.
  force.assign(n, 0.);
  const double smallest = *std::min_element(problem.separation.begin(), problem.separation.end());
  for (int j = 0; j < n; ++j)
    force[j] = static_cast<int>(start.size()) == n        ? start[j]
               : problem.separation[j] <= smallest + 1e-9 ? problem.total_force
                                                          : 0.;
  double total = std::accumulate(force.begin(), force.end(), 0.);
  if (!(total > 0.))
  {
    force.assign(n, problem.total_force / n);
    total = problem.total_force;
  }
  for (double& f : force)
    f *= problem.total_force / total;
  double& approach = solution.approach;
  approach = 0.;
  for (int pass = 0; pass < 4 * n + 8; ++pass)
  {
    ++solution.active_set_passes;
    std::vector<int> active;
    for (int j = 0; j < n; ++j)
      if (force[j] > 0.)
        active.push_back(j);
    if (active.empty())
      throw SolverFailure("influence-coefficient contact", "every pair left the active set");
    if (!newton_on_active(problem, active, friction, force, approach, solution.newton_steps))
      continue; // a pair unloaded itself: solve again without it
    // An unloaded pair that would penetrate enters with a small force (1e-3 of the load).
    int entering = -1;
    double deepest = 1e-15; // m: round-off of µm-sized gaps
    for (int j = 0; j < n; ++j)
    {
      const double depth = force[j] == 0. ? penetration(problem, force, friction, approach, j) : 0.;
      if (depth > deepest)
      {
        deepest = depth;
        entering = j;
      }
    }
    if (entering < 0)
    {
      solution.contact.resize(n);
      for (int j = 0; j < n; ++j)
        solution.contact[j] = near_field(problem, j, force[j]);
      return solution;
    }
    force[entering] = 1e-3 * problem.total_force;
  }
  throw SolverFailure("influence-coefficient contact",
                      "the active set of the tooth pairs did not settle in " +
                          std::to_string(4 * n + 8) + " passes");
}

// The friction forces of the normal solution `normal` (its F and e held): stick (t_j = 0) where
// |f_j| ≤ μ·F_j holds, else slip at the bound against the slip; an active set over stick and
// slip, started from `previous` (the last pass's: at the bound slips, else sticks).
std::vector<double> tangential(const MeshContactProblem& problem, const MeshContactSolution& normal,
                               const std::vector<double>& previous)
{
  const int n = normal.force.size();
  const double mu = problem.friction_coefficient;
  std::vector<double> base(n, 0.); // m, t_j of the normal loads and the rigid roll
  for (int j = 0; j < n; ++j)
  {
    base[j] = problem.slip_per_approach[j] * normal.approach;
    for (int k = 0; k < n; ++k)
      base[j] += problem.slip_under_force[j][k] * normal.force[k];
  }
  const auto slip_matrix = [&](int j, int k)
  { return problem.slip_under_friction[j][k] + (j == k ? normal.contact[j].compliance : 0.); };
  // State: 0 stick, ±1 slipping with f = ±μF; unloaded pairs carry none.
  std::vector<int> state(n, 0);
  std::vector<double> friction(n, 0.);
  for (int j = 0; j < n; ++j)
    if (normal.force[j] > 0. && !previous.empty())
      state[j] = std::abs(previous[j]) >= mu * normal.force[j] * (1. - 1e-12)
                     ? (previous[j] > 0. ? 1 : -1)
                     : 0;
  for (int pass = 0; pass < 4 * n + 8; ++pass)
  {
    std::vector<int> stick;
    for (int j = 0; j < n; ++j)
    {
      friction[j] = normal.force[j] > 0. ? state[j] * mu * normal.force[j] : 0.;
      if (normal.force[j] > 0. && state[j] == 0)
        stick.push_back(j);
    }
    if (!stick.empty())
    {
      const int m = stick.size();
      Eigen::MatrixXd a(m, m);
      Eigen::VectorXd b(m);
      for (int x = 0; x < m; ++x)
      {
        b[x] = -base[stick[x]];
        for (int k = 0; k < n; ++k)
          if (state[k] != 0)
            b[x] -= slip_matrix(stick[x], k) * friction[k];
        for (int y = 0; y < m; ++y)
          a(x, y) = slip_matrix(stick[x], stick[y]);
      }
      const Eigen::VectorXd f = a.partialPivLu().solve(b);
      for (int x = 0; x < m; ++x)
        friction[stick[x]] = f[x];
    }
    bool changed = false;
    for (int j = 0; j < n; ++j)
    {
      if (!(normal.force[j] > 0.))
        continue;
      const double bound = mu * normal.force[j];
      if (state[j] == 0 && std::abs(friction[j]) > bound)
      {
        state[j] = friction[j] > 0. ? 1 : -1; // it would need more than μF: it slips
        changed = true;
      }
      else if (state[j] != 0)
      {
        double slip = base[j];
        for (int k = 0; k < n; ++k)
          slip += slip_matrix(j, k) * friction[k];
        if (slip * state[j] > 0.) // it slides along its own friction force: it sticks
        {
          state[j] = 0;
          changed = true;
        }
      }
    }
    if (!changed)
      return friction;
  }
  throw SolverFailure("influence-coefficient contact",
                      "the flanks' stick and slip did not settle in " + std::to_string(4 * n + 8) +
                          " passes");
}
} // namespace

MeshContactSolution solve_mesh_contact(const MeshContactProblem& problem,
                                       const std::vector<double>& start)
{
  if (!(problem.friction_coefficient > 0.))
    return solve_normal(problem, start, {});
  // The normal and the tangential problem in turn (successive Tresca problems, as the exact
  // path's contact: contact/contact_problem.h), from the frictionless solution; the friction
  // forces change by a factor of order μ a pass.
  MeshContactSolution solution = solve_normal(problem, start, {});
  std::vector<double> friction;
  for (unsigned int pass = 1; pass <= 100; ++pass)
  {
    const std::vector<double> next = tangential(problem, solution, friction);
    double change = 0.;
    for (std::size_t j = 0; j < next.size(); ++j)
      change = std::max(change, std::abs(next[j] - (friction.empty() ? 0. : friction[j])));
    friction = next;
    solution = solve_normal(problem, solution.force, friction);
    solution.friction_passes = pass;
    // 1e-12 of the load: round-off, as the normal Newton's.
    if (change <= 1e-12 * problem.total_force)
    {
      solution.friction = friction; // those the forces were solved with
      return solution;
    }
  }
  throw SolverFailure("influence-coefficient contact",
                      "the friction forces did not settle in 100 passes of the normal and the "
                      "tangential problem");
}
} // namespace gearstiff::stiffness
