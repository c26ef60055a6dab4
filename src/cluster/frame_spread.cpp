#include "cluster/frame_spread.h"

#include <stdexcept>

namespace urbis {

std::vector<uint32_t> framesOfRank(const std::vector<uint32_t>& frames, int rank, int ranks) {
    if (ranks < 1 || rank < 0 || rank >= ranks) throw std::invalid_argument("framesOfRank: no such rank");
    std::vector<uint32_t> share;
    for (size_t i = size_t(rank); i < frames.size(); i += size_t(ranks)) share.push_back(frames[i]);
    return share;
}

} // namespace urbis
