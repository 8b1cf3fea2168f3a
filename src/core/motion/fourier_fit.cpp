#include "dressed_human/core/motion/fourier_fit.h"

#include <cmath>
#include <string>

#include <Eigen/QR>

namespace dressed_human {
namespace {}  // namespace

std::vector<double> unwrapAngles(const std::vector<double>& wrapped) {
  std::vector<double> unwrapped(wrapped.size());
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    if (i == 0) {
      unwrapped[i] = wrapped[i];
      continue;
    }
    const double step = std::remainder(wrapped[i] - wrapped[i - 1], 2.0 * M_PI);
    unwrapped[i] = unwrapped[i - 1] + step;
  }
  return unwrapped;
}

FourierFit fitFourierSeries(const std::vector<double>& times, const std::vector<double>& values, double period,
                            std::size_t order, bool with_linear_term) {
  if (times.size() != values.size()) {
    throw MotionError("Fourier fit: " + std::to_string(times.size()) + " times but " + std::to_string(values.size()) +
                      " values");
  }
  if (!std::isfinite(period) || period <= 0.0) throw MotionError("Fourier fit: the period must be finite and > 0");
  const std::size_t offset = with_linear_term ? 1 : 0;
  const std::size_t unknowns = offset + 1 + 2 * order;
  if (values.size() < unknowns) {
    throw MotionError("Fourier fit: order " + std::to_string(order) + " needs at least " + std::to_string(unknowns) +
                      " samples, got " + std::to_string(values.size()));
  }
  const auto rows = static_cast<Eigen::Index>(values.size());
  Eigen::MatrixXd design(rows, static_cast<Eigen::Index>(unknowns));
  Eigen::VectorXd rhs(rows);
  const double omega = 2.0 * M_PI / period;
  for (Eigen::Index i = 0; i < rows; ++i) {
    const double time = times[static_cast<std::size_t>(i)];
    const double value = values[static_cast<std::size_t>(i)];
    if (!std::isfinite(time) || !std::isfinite(value)) {
      throw MotionError("Fourier fit: sample " + std::to_string(i + 1) + " is not a finite number");
    }
    rhs[i] = value;
    // The linear term in cycles rather than seconds keeps its column on the scale of the others.
    if (with_linear_term) design(i, 0) = time / period;
    design(i, static_cast<Eigen::Index>(offset)) = 0.5;
    for (std::size_t n = 1; n <= order; ++n) {
      const double angle = static_cast<double>(n) * omega * time;
      design(i, static_cast<Eigen::Index>(offset + n)) = std::cos(angle);
      design(i, static_cast<Eigen::Index>(offset + order + n)) = std::sin(angle);
    }
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(design);
  const Eigen::VectorXd coefficients = qr.solve(rhs);
  if (!coefficients.allFinite()) throw MotionError("Fourier fit: the least-squares problem is singular");

  FourierFit fit;
  fit.series.period = period;
  if (with_linear_term) fit.linear_rate = coefficients[0] / period;
  fit.series.a0 = coefficients[static_cast<Eigen::Index>(offset)];
  for (std::size_t n = 1; n <= order; ++n) {
    fit.series.a.push_back(coefficients[static_cast<Eigen::Index>(offset + n)]);
    fit.series.b.push_back(coefficients[static_cast<Eigen::Index>(offset + order + n)]);
  }
  fit.rms_residual = std::sqrt((design * coefficients - rhs).squaredNorm() / static_cast<double>(rows));
  return fit;
}

FourierFit fitFourierSeriesToTolerance(const std::vector<double>& times, const std::vector<double>& values,
                                       double period, double tolerance, std::size_t max_order, bool with_linear_term) {
  FourierFit fit;
  for (std::size_t order = 0; order <= max_order; ++order) {
    fit = fitFourierSeries(times, values, period, order, with_linear_term);
    if (fit.rms_residual <= tolerance) return fit;
  }
  fit.reached_tolerance = false;
  return fit;
}

}  // namespace dressed_human
