#include "servobench/machine/card_group.hpp"

#include <algorithm>

namespace servobench::machine {

std::vector<std::size_t> card_axes_of(const motion::CoordSystem& cs) {
  std::vector<std::size_t> v;
  for (int a : cs.axes()) v.push_back(static_cast<std::size_t>(a - 1));
  return v;
}

namespace {

bool in_group(const std::vector<std::size_t>& axes, std::size_t k) {
  return std::find(axes.begin(), axes.end(), k) != axes.end();
}

void set_outside(motion::PathGenerator& g, const std::vector<std::size_t>& axes, const std::vector<double>& pos) {
  for (std::size_t k = 0; k < pos.size(); ++k) {
    if (in_group(axes, k)) continue;
    try {
      g.set_aux_position(static_cast<int>(k + 1), pos[k]);
    } catch (const motion::MotionCommandRefused&) {
      // a buffered move of this axis still runs: it keeps its own position
    }
  }
}

void append_aux(const motion::PathGenerator& g, std::vector<std::pair<std::size_t, double>>& out) {
  for (int a : g.aux_axes()) out.emplace_back(static_cast<std::size_t>(a - 1), g.aux_position(a));
}

}  // namespace

CrdPairGroup::CrdPairGroup(const motion::CoordSystem& coords, const motion::PathSetup& setup,
                           const motion::CrdPoint& start, double resume_tolerance)
    : CardGroup(card_axes_of(coords)), pair_(coords, setup, start, resume_tolerance) {}

void CrdPairGroup::aux_positions(std::vector<std::pair<std::size_t, double>>& out) const {
  out.clear();
  for (int a : pair_.aux_axes()) out.emplace_back(static_cast<std::size_t>(a - 1), pair_.aux_position(a));
}

void CrdPairGroup::set_outside_positions(const std::vector<double>& profile_pos) {
  for (int k = 0; k < 2; ++k)
    if (!pair_.fifo(k).busy()) set_outside(pair_.fifo(k), axes(), profile_pos);
}

PathGroup::PathGroup(const motion::CoordSystem& coords, const motion::PathSetup& setup, const motion::CrdPoint& start)
    : CardGroup(card_axes_of(coords)), gen_(coords, setup, start) {}

void PathGroup::aux_positions(std::vector<std::pair<std::size_t, double>>& out) const {
  out.clear();
  append_aux(gen_, out);
}

void PathGroup::set_outside_positions(const std::vector<double>& profile_pos) {
  if (!gen_.busy()) set_outside(gen_, axes(), profile_pos);
}

void CrdPairGroup::set_input(int type, int index, bool active) {
  for (int k = 0; k < 2; ++k) pair_.fifo(k).set_input(type, index, active);  // both FIFOs map stops (V129)
}

bool CrdPairGroup::limit_enabled(std::size_t axis, bool positive) const {
  if (axis >= 16) return true;
  const motion::PathState& st = pair_.state();  // the running FIFO's flags (BufLmtsOn/Off executed so far)
  return ((positive ? st.limits_pos : st.limits_neg) >> axis) & 1u;
}

}  // namespace servobench::machine
