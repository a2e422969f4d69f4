#include "fitconnect/hyper_circle_fit.h"

#include <cmath>

namespace curvebench {

FittedCircle hyper_circle_fit(std::span<const Point2> points) {
  const double m = static_cast<double>(points.size());
  double mean_x = 0.0, mean_y = 0.0;
  for (const Point2& p : points) {
    mean_x += p.x;
    mean_y += p.y;
  }
  mean_x /= m;
  mean_y /= m;

  // Moments of the centred coordinates; z_last is kept for the degenerate branch (spec 2.1).
  double m_xx = 0.0, m_yy = 0.0, m_xy = 0.0, m_xz = 0.0, m_yz = 0.0, m_zz = 0.0, z_last = 0.0;
  for (const Point2& p : points) {
    const double x = p.x - mean_x, y = p.y - mean_y, z = x * x + y * y;
    m_xy += x * y;
    m_xx += x * x;
    m_yy += y * y;
    m_xz += x * z;
    m_yz += y * z;
    m_zz += z * z;
    z_last = z;
  }
  m_xx /= m;
  m_yy /= m;
  m_xy /= m;
  m_xz /= m;
  m_yz /= m;
  m_zz /= m;

  const double m_z = m_xx + m_yy;
  const double cov_xy = m_xx * m_yy - m_xy * m_xy;
  const double var_z = m_zz - m_z * m_z;
  const double a2 = 4.0 * cov_xy - 3.0 * m_z * m_z - m_zz;
  const double a1 = var_z * m_z + 4.0 * cov_xy * m_z - m_xz * m_xz - m_yz * m_yz;
  const double a0 = m_xz * (m_xz * m_yy - m_yz * m_xy) + m_yz * (m_yz * m_xx - m_xz * m_xy) - var_z * cov_xy;

  // Newton on P(eta) = 4 eta^4 + a2 eta^2 + a1 eta + a0 from eta = 0, evaluated in the
  // authors' Horner forms so that the iterates match theirs.
  double eta = 0.0, p_eta = a0;
  for (int step = 0; step < 99; ++step) {
    const double slope = a1 + eta * (2.0 * a2 + 16.0 * eta * eta);
    const double next = eta - p_eta / slope;
    if (next == eta || !std::isfinite(next)) break;
    const double p_next = a0 + next * (a1 + next * (a2 + 4.0 * next * next));
    if (std::fabs(p_next) >= std::fabs(p_eta)) break;
    eta = next;
    p_eta = p_next;
  }

  const double det = eta * eta - eta * m_z + cov_xy;
  double u, v;
  // The authors' test is absolute: D below 1e-20, in input units to the fourth. It is meant
  // for collinear neighbourhoods (spec section 3), but D scales as (width x length)^2, so it
  // also fires on curved or noisy neighbourhoods once they are small enough in the input's
  // units: on dense samples (the benchmark's noisy rose at 10^6) or small coordinates, nearly
  // every fit. The branch is taken only where the points are also collinear at their own
  // scale: D at most 1e-10 of m_z^2, a width under about 1e-5 of the length (exactly collinear
  // points leave a few 1e-12 of rounding). A fit the absolute test lets through is the authors',
  // so the departure is confined to fits whose branch the units decided.
  constexpr double kCollinearAtItsOwnScale = 1e-10;
  const bool on_a_line = det < 1e-20 && det <= kCollinearAtItsOwnScale * m_z * m_z;
  if (on_a_line) {
    // Collinear: the authors' fallback centre, kept for fidelity (spec section 3).
    u = (points[1].y - points[0].y) / std::sqrt(z_last);
    v = -(points[1].x - points[0].x) / std::sqrt(z_last);
  } else {
    u = (m_xz * (m_yy - eta) - m_yz * m_xy) / det / 2.0;
    v = (m_yz * (m_xx - eta) - m_xz * m_xy) / det / 2.0;
  }
  return {{u + mean_x, v + mean_y}, std::sqrt(u * u + v * v + m_z - eta - eta), on_a_line};
}

}  // namespace curvebench
