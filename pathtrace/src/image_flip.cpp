// LDR-FLIP (Andersson et al., HPG 2020), written from the paper's description: a colour pipeline
// (contrast-sensitivity filtering in the opponent space YCxCz, then the HyAB distance of
// Hunt-adjusted L*a*b*) and a feature pipeline (edges and points of the luminance, from first and
// second derivatives of a Gaussian), combined as colour^(1 - feature). Every filter here is a sum
// of separable Gaussians, so it is applied as a horizontal and a vertical 1D pass.
#include <lintel/reference/image_flip.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace lintel {
namespace {

constexpr double kPi = 3.14159265358979323846;

// sRGB primaries, D65 white (IEC 61966-2-1).
const glm::dmat3 kRgbToXyz = glm::transpose(glm::dmat3(0.4124564, 0.3575761, 0.1804375,  //
                                                       0.2126729, 0.7151522, 0.0721750,  //
                                                       0.0193339, 0.1191920, 0.9503041));
const glm::dvec3 kWhite = kRgbToXyz * glm::dvec3(1.0);

double srgb_to_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Opponent space of the CSFs (Johnson and Fairchild): achromatic, red-green, blue-yellow.
glm::dvec3 xyz_to_ycxcz(glm::dvec3 xyz) {
  const glm::dvec3 r = xyz / kWhite;
  return {116.0 * r.y - 16.0, 500.0 * (r.x - r.y), 200.0 * (r.y - r.z)};
}

glm::dvec3 ycxcz_to_xyz(glm::dvec3 c) {
  const double y = (c.x + 16.0) / 116.0;
  return glm::dvec3(c.y / 500.0 + y, y, y - c.z / 200.0) * kWhite;
}

double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// L*a*b* with a and b scaled by 0.01 L* (the Hunt effect: colourfulness falls with lightness).
glm::dvec3 hunt_lab_of_linear_rgb(glm::dvec3 rgb) {
  const glm::dvec3 r = (kRgbToXyz * rgb) / kWhite;
  const double l = 116.0 * lab_f(r.y) - 16.0;
  const double a = 500.0 * (lab_f(r.x) - lab_f(r.y)), b = 200.0 * (lab_f(r.y) - lab_f(r.z));
  return {l, 0.01 * l * a, 0.01 * l * b};
}

double hyab(glm::dvec3 p, glm::dvec3 q) {
  return std::abs(p.x - q.x) + std::sqrt((p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z));
}

struct Plane {
  uint32_t w = 0, h = 0;
  std::vector<double> v;
  double at(int x, int y) const {
    x = std::clamp(x, 0, int(w) - 1);
    y = std::clamp(y, 0, int(h) - 1);
    return v[size_t(y) * w + size_t(x)];
  }
};

// kx along rows, then ky along columns; both of odd length 2r+1, centred; borders clamped.
Plane convolve(const Plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
  const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
  Plane mid{in.w, in.h, std::vector<double>(in.v.size())}, out = mid;
  for (int y = 0; y < int(in.h); ++y)
    for (int x = 0; x < int(in.w); ++x) {
      double s = 0.0;
      for (int k = -rx; k <= rx; ++k) s += kx[size_t(k + rx)] * in.at(x + k, y);
      mid.v[size_t(y) * in.w + size_t(x)] = s;
    }
  for (int y = 0; y < int(in.h); ++y)
    for (int x = 0; x < int(in.w); ++x) {
      double s = 0.0;
      for (int k = -ry; k <= ry; ++k) s += ky[size_t(k + ry)] * mid.at(x, y + k);
      out.v[size_t(y) * in.w + size_t(x)] = s;
    }
  return out;
}

// One channel's contrast sensitivity as a spatial filter: sum over i of
// a_i sqrt(pi / b_i) exp(-pi^2 d^2 / b_i), d in degrees, normalised to sum 1 (the paper's table).
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic{1.0, 0.0047, 0.0, 1e-5}, kCsfRedGreen{1.0, 0.0053, 0.0, 1e-5},
    kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};

Plane csf_filter(const Plane& in, const Csf& c, double ppd) {
  const double b_max = std::max(c.b1, c.b2);
  const int r = int(std::ceil(3.0 * std::sqrt(b_max / (2.0 * kPi * kPi)) * ppd));
  Plane sum{in.w, in.h, std::vector<double>(in.v.size(), 0.0)};
  double total = 0.0;
  for (const auto& [a, b] : {std::pair{c.a1, c.b1}, std::pair{c.a2, c.b2}}) {
    if (a == 0.0) continue;
    std::vector<double> g(size_t(2 * r + 1));
    double g_sum = 0.0;
    for (int k = -r; k <= r; ++k) {
      const double d = double(k) / ppd;
      g[size_t(k + r)] = std::exp(-kPi * kPi * d * d / b);
      g_sum += g[size_t(k + r)];
    }
    const double scale = a * std::sqrt(kPi / b);
    const Plane term = convolve(in, g, g);
    for (size_t p = 0; p < sum.v.size(); ++p) sum.v[p] += scale * term.v[p];
    total += scale * g_sum * g_sum;
  }
  for (double& v : sum.v) v /= total;
  return sum;
}

// Edge (first derivative) and point (second derivative) magnitudes of the luminance, with the
// derivative-of-Gaussian kernels of the paper: sigma = 0.5 * 0.082 degrees; each kernel's
// positive weights sum to 1 and its negative weights to -1, so a flat image has no features.
struct Features {
  Plane edge, point;
};

Features detect_features(const Plane& luminance, double ppd) {
  const double sigma = 0.5 * 0.082 * ppd;
  const int r = int(std::ceil(3.0 * sigma));
  const size_t n = size_t(2 * r + 1);
  std::vector<double> g(n), d1(n), d2(n);
  double g_sum = 0.0, d1_pos = 0.0, d2_pos = 0.0, d2_neg = 0.0;
  for (int k = -r; k <= r; ++k) {
    const double x = double(k), gk = std::exp(-x * x / (2.0 * sigma * sigma));
    g[size_t(k + r)] = gk;
    d1[size_t(k + r)] = -x * gk;
    d2[size_t(k + r)] = (x * x / (sigma * sigma) - 1.0) * gk;
    g_sum += gk;
    d1_pos += std::max(0.0, -x * gk);
    (d2[size_t(k + r)] > 0.0 ? d2_pos : d2_neg) += d2[size_t(k + r)];
  }
  for (size_t k = 0; k < n; ++k) {
    g[k] /= g_sum;
    d1[k] /= d1_pos;
    d2[k] /= d2[k] > 0.0 ? d2_pos : -d2_neg;
  }
  const Plane ex = convolve(luminance, d1, g), ey = convolve(luminance, g, d1);
  const Plane px = convolve(luminance, d2, g), py = convolve(luminance, g, d2);
  Features f{ex, px};
  for (size_t p = 0; p < luminance.v.size(); ++p) {
    f.edge.v[p] = std::hypot(ex.v[p], ey.v[p]);
    f.point.v[p] = std::hypot(px.v[p], py.v[p]);
  }
  return f;
}

struct Prepared {
  Plane y, cx, cz;  // opponent channels, unfiltered
};

Prepared prepare(const std::vector<glm::vec3>& srgb, uint32_t w, uint32_t h) {
  Prepared p{{w, h, std::vector<double>(srgb.size())},
             {w, h, std::vector<double>(srgb.size())},
             {w, h, std::vector<double>(srgb.size())}};
  for (size_t i = 0; i < srgb.size(); ++i) {
    const glm::dvec3 lin(srgb_to_linear(srgb[i].r), srgb_to_linear(srgb[i].g), srgb_to_linear(srgb[i].b));
    const glm::dvec3 c = xyz_to_ycxcz(kRgbToXyz * lin);
    p.y.v[i] = c.x;
    p.cx.v[i] = c.y;
    p.cz.v[i] = c.z;
  }
  return p;
}

// The filtered opponent colour back to clamped linear RGB, then to Hunt-adjusted L*a*b*.
std::vector<glm::dvec3> perceived_colour(const Prepared& p, double ppd) {
  const Plane y = csf_filter(p.y, kCsfAchromatic, ppd), cx = csf_filter(p.cx, kCsfRedGreen, ppd),
              cz = csf_filter(p.cz, kCsfBlueYellow, ppd);
  const glm::dmat3 xyz_to_rgb = glm::inverse(kRgbToXyz);
  std::vector<glm::dvec3> out(y.v.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::dvec3 rgb = glm::clamp(xyz_to_rgb * ycxcz_to_xyz({y.v[i], cx.v[i], cz.v[i]}), 0.0, 1.0);
    out[i] = hunt_lab_of_linear_rgb(rgb);
  }
  return out;
}

}  // namespace

double flip_ldr(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, uint32_t width,
                uint32_t height, const FlipOptions& options, std::vector<float>* error_map) {
  assert(width >= 1 && height >= 1);
  assert(reference.size() == size_t(width) * height && test.size() == reference.size());
  const double ppd = options.pixels_per_degree;
  constexpr double kQc = 0.7, kQf = 0.5, kPc = 0.4, kPt = 0.95;
  // The largest colour difference: green against blue, through the same distance.
  const double c_max =
      std::pow(hyab(hunt_lab_of_linear_rgb({0.0, 1.0, 0.0}), hunt_lab_of_linear_rgb({0.0, 0.0, 1.0})), kQc);

  const Prepared pr = prepare(reference, width, height), pt = prepare(test, width, height);
  const std::vector<glm::dvec3> lab_r = perceived_colour(pr, ppd), lab_t = perceived_colour(pt, ppd);
  // Features from the unfiltered luminance normalised to [0, 1]: (Y' + 16) / 116 = Y / Y_white.
  auto normalised_luminance = [](const Plane& y) {
    Plane out = y;
    for (double& v : out.v) v = (v + 16.0) / 116.0;
    return out;
  };
  const Features fr = detect_features(normalised_luminance(pr.y), ppd);
  const Features ft = detect_features(normalised_luminance(pt.y), ppd);

  if (error_map) error_map->assign(reference.size(), 0.0f);
  double sum = 0.0;
  for (size_t i = 0; i < reference.size(); ++i) {
    // Colour: HyAB^qc mapped to [0, 1], compressing the top (1 - pc) of the range into (pt, 1].
    const double dc = std::pow(hyab(lab_r[i], lab_t[i]), kQc);
    const double ec =
        dc < kPc * c_max ? kPt / (kPc * c_max) * dc : kPt + (dc - kPc * c_max) / (c_max - kPc * c_max) * (1.0 - kPt);
    const double df = std::max(std::abs(fr.edge.v[i] - ft.edge.v[i]), std::abs(fr.point.v[i] - ft.point.v[i]));
    const double ef = std::pow(std::min(1.0, df / std::sqrt(2.0)), kQf);
    const double e = ec <= 0.0 ? 0.0 : std::pow(std::min(ec, 1.0), 1.0 - ef);
    if (error_map) (*error_map)[i] = float(e);
    sum += e;
  }
  return sum / double(reference.size());
}

std::vector<glm::vec3> tonemap_for_flip(const std::vector<glm::vec3>& linear, float exposure) {
  std::vector<glm::vec3> out(linear.size());
  for (size_t i = 0; i < linear.size(); ++i) {
    const glm::vec3 x = glm::max(linear[i], glm::vec3(0.0f)) * exposure;
    const glm::vec3 aces = glm::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c)
      out[i][c] = aces[c] <= 0.0031308f ? 12.92f * aces[c] : 1.055f * std::pow(aces[c], 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

float key_exposure(const std::vector<glm::vec3>& linear) {
  double log_sum = 0.0;
  size_t count = 0;
  for (const glm::vec3& c : linear) {
    const double lum = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    if (!(lum > 0.0)) continue;
    log_sum += std::log2(std::max(lum, 1e-6));
    ++count;
  }
  return count ? float(0.18 / std::exp2(log_sum / double(count))) : 1.0f;
}

}  // namespace lintel
