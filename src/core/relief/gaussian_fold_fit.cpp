#include "dressed_human/core/relief/gaussian_fold_fit.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

double gridCoordinate(int index, int count, double half_extent) {
  // Cell-centred samples: never exactly on the creases' end points at the border.
  return (-1.0 + (2.0 * index + 1.0) / count) * half_extent;
}

}  // namespace

ReliefSample GaussianFoldApproximation::sample(double x, double y) const {
  ReliefSample result;
  for (const GaussianTerm& term : terms_) {
    const double dx = x - term.centre_x;
    const double dy = y - term.centre_y;
    const double inv_x = 1.0 / (term.sigma_x * term.sigma_x);
    const double inv_y = 1.0 / (term.sigma_y * term.sigma_y);
    const double value = term.amplitude * std::exp(-0.5 * (dx * dx * inv_x + dy * dy * inv_y));
    result.height += value;
    result.slope.x() -= value * dx * inv_x;
    result.slope.y() -= value * dy * inv_y;
  }
  return result;
}

GaussianFoldApproximation fitGaussians(const BucklingPattern& pattern, int term_count,
                                       const GaussianFitOptions& options) {
  if (term_count < 1) {
    std::ostringstream message;
    message << "fitGaussians: term_count must be >= 1, got " << term_count;
    throw std::invalid_argument(message.str());
  }
  if (options.samples_per_axis < 4 || options.centres_per_axis < 2) {
    std::ostringstream message;
    message << "fitGaussians: samples_per_axis must be >= 4 and centres_per_axis >= 2, got " << options.samples_per_axis
            << " and " << options.centres_per_axis;
    throw std::invalid_argument(message.str());
  }
  const double lx = pattern.cell().half_width_x;
  const double ly = pattern.footprintHalfLength();
  const int samples = options.samples_per_axis;
  const Eigen::Index sample_count = static_cast<Eigen::Index>(samples) * samples;
  Eigen::VectorXd target(sample_count);
  Eigen::VectorXd xs(sample_count), ys(sample_count);
  for (int row = 0; row < samples; ++row) {
    for (int column = 0; column < samples; ++column) {
      const Eigen::Index at = static_cast<Eigen::Index>(row) * samples + column;
      xs[at] = gridCoordinate(column, samples, lx);
      ys[at] = gridCoordinate(row, samples, ly);
      target[at] = pattern.heightAt(xs[at], ys[at]);
    }
  }

  // Dictionary: centres on an inclusive grid (creases run to the borders), widths from thin
  // (a crease) to broad (a whole half cell).
  const double width_factors_x[] = {0.1, 0.2, 0.4, 0.8, 1.6};
  const double width_factors_y[] = {0.15, 0.3, 0.6, 1.2};
  std::vector<GaussianTerm> dictionary;
  const int centres = options.centres_per_axis;
  for (int cy = 0; cy < centres; ++cy) {
    for (int cx = 0; cx < centres; ++cx) {
      for (double fx : width_factors_x) {
        for (double fy : width_factors_y) {
          GaussianTerm atom;
          atom.amplitude = 1.0;
          atom.centre_x = (-1.0 + 2.0 * cx / (centres - 1)) * lx;
          atom.centre_y = (-1.0 + 2.0 * cy / (centres - 1)) * ly;
          atom.sigma_x = fx * lx;
          atom.sigma_y = fy * ly;
          dictionary.push_back(atom);
        }
      }
    }
  }
  const Eigen::Index atom_count = static_cast<Eigen::Index>(dictionary.size());
  Eigen::MatrixXd atoms(sample_count, atom_count);
  for (Eigen::Index column = 0; column < atom_count; ++column) {
    const GaussianFoldApproximation single({dictionary[static_cast<std::size_t>(column)]});
    for (Eigen::Index at = 0; at < sample_count; ++at) atoms(at, column) = single.sample(xs[at], ys[at]).height;
  }
  const Eigen::VectorXd atom_norms = atoms.colwise().norm().transpose();

  std::vector<Eigen::Index> chosen;
  Eigen::VectorXd amplitudes;
  Eigen::VectorXd residual = target;
  const double target_norm = target.norm();
  for (int pick = 0; pick < term_count; ++pick) {
    if (residual.norm() <= 1e-12 * std::max(1.0, target_norm)) break;  // flat pattern or exact fit
    const Eigen::VectorXd correlation = (atoms.transpose() * residual).cwiseAbs().cwiseQuotient(atom_norms);
    Eigen::Index best = 0;
    correlation.maxCoeff(&best);
    chosen.push_back(best);
    Eigen::MatrixXd selected(sample_count, static_cast<Eigen::Index>(chosen.size()));
    for (std::size_t k = 0; k < chosen.size(); ++k) selected.col(static_cast<Eigen::Index>(k)) = atoms.col(chosen[k]);
    amplitudes = selected.colPivHouseholderQr().solve(target);
    residual = target - selected * amplitudes;
  }
  std::vector<GaussianTerm> terms;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    GaussianTerm term = dictionary[static_cast<std::size_t>(chosen[k])];
    term.amplitude = amplitudes[static_cast<Eigen::Index>(k)];
    terms.push_back(term);
  }
  return GaussianFoldApproximation(std::move(terms));
}

double rmsApproximationError(const BucklingPattern& pattern, const GaussianFoldApproximation& approximation,
                             int samples_per_axis) {
  if (samples_per_axis < 1) {
    std::ostringstream message;
    message << "rmsApproximationError: samples_per_axis must be >= 1, got " << samples_per_axis;
    throw std::invalid_argument(message.str());
  }
  const double lx = pattern.cell().half_width_x;
  const double ly = pattern.footprintHalfLength();
  double sum = 0.0;
  for (int row = 0; row < samples_per_axis; ++row) {
    for (int column = 0; column < samples_per_axis; ++column) {
      // Offset by a third of a cell from the fit grid so the error is measured off the fit samples.
      const double x = (-1.0 + (2.0 * column + 1.0 / 3.0 + 0.5) / samples_per_axis) * lx;
      const double y = (-1.0 + (2.0 * row + 1.0 / 3.0 + 0.5) / samples_per_axis) * ly;
      const double difference = approximation.sample(x, y).height - pattern.heightAt(x, y);
      sum += difference * difference;
    }
  }
  return std::sqrt(sum / (static_cast<double>(samples_per_axis) * samples_per_axis));
}

}  // namespace dressed_human
