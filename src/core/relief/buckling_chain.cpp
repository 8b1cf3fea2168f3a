#include "dressed_human/core/relief/buckling_chain.h"

#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

PatternKind parseKind(char letter, std::size_t position) {
  switch (letter) {
    case 'I':
    case 'i':
      return PatternKind::I;
    case 'Y':
    case 'y':
      return PatternKind::Y;
    case 'X':
    case 'x':
      return PatternKind::X;
    default:
      break;
  }
  std::ostringstream message;
  message << "chain pattern string: character '" << letter << "' at position " << position << " is not one of I, Y, X";
  throw std::invalid_argument(message.str());
}

// Left-to-right propagation; a Y takes whatever its left neighbour offers.
bool orientFrom(const std::vector<PatternKind>& kinds, bool first_y_split_left, std::vector<ChainCell>& cells) {
  cells.assign(kinds.size(), ChainCell{});
  for (std::size_t index = 0; index < kinds.size(); ++index) {
    ChainCell& cell = cells[index];
    cell.kind = kinds[index];
    const bool left_must_split = index > 0 && cells[index - 1].split_right;
    switch (cell.kind) {
      case PatternKind::I:
        if (left_must_split) return false;
        break;
      case PatternKind::X:
        if (index > 0 && !left_must_split) return false;
        cell.split_left = cell.split_right = true;
        break;
      case PatternKind::Y:
        cell.split_left = index == 0 ? first_y_split_left : left_must_split;
        cell.split_right = !cell.split_left;
        break;
    }
  }
  return true;
}

}  // namespace

std::vector<ChainCell> orientChain(const std::string& kinds, bool periodic) {
  if (kinds.empty()) throw std::invalid_argument("chain pattern string is empty");
  std::vector<PatternKind> parsed;
  for (std::size_t index = 0; index < kinds.size(); ++index) parsed.push_back(parseKind(kinds[index], index));
  std::vector<ChainCell> cells;
  for (bool first_split_left : {false, true}) {
    if (!orientFrom(parsed, first_split_left, cells)) continue;
    if (!periodic || cells.back().split_right == cells.front().split_left) return cells;
  }
  std::ostringstream message;
  message << "chain pattern \"" << kinds << "\"" << (periodic ? " (periodic)" : "")
          << " cannot be oriented: a split edge (Y/X) would have to meet an I edge";
  throw std::invalid_argument(message.str());
}

BucklingChain buildBucklingChain(const std::string& kinds, double alpha, const BucklingCell& cell,
                                 OutOfDomainPolicy policy) {
  const std::vector<ChainCell> oriented = orientChain(kinds, false);
  BucklingChain chain;
  Eigen::Isometry3d to_world = Eigen::Isometry3d::Identity();
  const double lx = cell.half_width_x;
  for (std::size_t index = 0; index < oriented.size(); ++index) {
    const ChainCell& entry = oriented[index];
    chain.cells.emplace_back(entry.kind, alpha, cell, policy, entry.kind == PatternKind::Y && entry.split_right);
    if (index > 0) {
      const BucklingPattern& previous = chain.cells[index - 1];
      const BucklingPattern& current = chain.cells.back();
      if (previous.splitRight() != current.splitLeft()) {
        // Happens only when the policy turned a Y/X into an I pattern mid-chain.
        std::ostringstream message;
        message << "buildBucklingChain: joint " << index - 1 << "-" << index
                << " meets a split edge with an I edge (alpha below the Y/X domain with "
                   "fallBackToIPattern)";
        throw std::domain_error(message.str());
      }
      const double bend = previous.splitRight() ? previous.solution().bend_angle : 0.0;
      to_world = to_world * Eigen::Translation3d(lx, 0.0, 0.0) * Eigen::AngleAxisd(bend, Eigen::Vector3d::UnitY()) *
                 Eigen::Translation3d(lx, 0.0, 0.0);
      chain.joint_bend_angles.push_back(bend);
    }
    chain.cell_to_world.push_back(to_world);
  }
  return chain;
}

}  // namespace dressed_human
