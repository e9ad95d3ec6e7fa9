#pragma once
// What one seeded run leaves behind, whichever framework ran it.
namespace hystbench::peer {

struct PeerTrial {
  double best = 0.0;          // final best fitness
  long evaluations = 0;       // fitness evaluations actually spent
  double wall_seconds = 0.0;  // initial population included
};

}  // namespace hystbench::peer
