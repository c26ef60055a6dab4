// The tiles of a frame handed out one at a time to whichever worker asks next: the ranks of an MPI
// render (rank 0 answers for them) and the host threads that drive a process's GPUs.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace urbis {

/// A dynamic queue of indices 0..count-1 (a frame's tiles, a sequence's frames), safe to take from
/// on any thread: a slow worker simply takes fewer.
class TileQueue {
public:
    explicit TileQueue(size_t count) : count_(count) {}

    /// The next index, or -1 once every one has been handed out.
    int32_t take() {
        const size_t i = next_++;
        return i < count_ ? int32_t(i) : -1;
    }

private:
    std::atomic<size_t> next_{0};
    size_t count_;
};

/// What each worker of a tile queue did.
struct TileShare {
    std::vector<uint32_t> tilesByWorker;  ///< tiles rendered by each worker (rank, or device), the first first
    uint64_t rays = 0;                    ///< rays traced by all workers
};

} // namespace urbis
