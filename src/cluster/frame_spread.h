// Frames of a sequence spread over the ranks of an MPI job: each rank renders whole frames of its
// share, by itself, as one process would (the frame loop of `urbis render --frames` runs over it).
#pragma once

#include <cstdint>
#include <vector>

namespace urbis {

/// The frames of `frames` that rank `rank` of `ranks` renders: every `ranks`-th one from its own
/// index on (round robin, so that ranks share the costly and the cheap ends of a sequence), in
/// the sequence's order. Over all ranks each frame comes exactly once. Throws
/// std::invalid_argument unless 0 <= rank < ranks.
std::vector<uint32_t> framesOfRank(const std::vector<uint32_t>& frames, int rank, int ranks);

} // namespace urbis
