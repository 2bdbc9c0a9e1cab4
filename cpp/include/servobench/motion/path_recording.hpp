// A recorded coordinated path, one row per motion cycle, from any stepper with the PathGenerator interface
// (PathGenerator, CrdFifoPair): time ms, coordinate position (dim columns), motor positions (coords().axes()
// order), path speed and acceleration, segments done, GPO word, and the positions of the outside axes
// (aux_axes() at the end, in that order).
#pragma once

#include <cstddef>
#include <vector>

namespace servobench::motion {

struct PathRecording {
  int dim = 0;
  std::vector<int> axes, aux_axes;
  std::vector<double> t_ms, crd, axis_pos, speed, acc, segments, gpo, aux;
  std::size_t size() const { return t_ms.size(); }
};

// Steps `g` `ticks` cycles, or until g.done() when until_done.
template <class G>
PathRecording record_path(G& g, std::size_t ticks, bool until_done) {
  PathRecording r;
  r.dim = g.coords().dim();
  r.axes = g.coords().axes();
  r.aux_axes = g.aux_axes();
  std::vector<double> ax(r.axes.size());
  for (std::size_t k = 0; k < ticks; ++k) {
    if (until_done && g.done()) break;
    const auto& s = g.step();
    r.t_ms.push_back(s.t_ms);
    for (int i = 0; i < r.dim; ++i) r.crd.push_back(s.pos[static_cast<std::size_t>(i)]);
    g.coords().to_axes(s.pos, ax.data());
    r.axis_pos.insert(r.axis_pos.end(), ax.begin(), ax.end());
    r.speed.push_back(s.speed);
    r.acc.push_back(s.acc);
    r.segments.push_back(static_cast<double>(s.segments_done));
    r.gpo.push_back(static_cast<double>(s.do_words[0]));
    for (int a : r.aux_axes) r.aux.push_back(g.aux_position(a));
  }
  return r;
}

}  // namespace servobench::motion
