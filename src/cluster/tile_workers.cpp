#include "cluster/tile_workers.h"

#include <atomic>
#include <exception>
#include <thread>

namespace urbis {

void runOnWorkerThreads(size_t workers, const std::function<void(size_t)>& work) {
    std::vector<std::exception_ptr> failures(workers);
    std::vector<std::thread> threads;
    for (size_t w = 0; w < workers; ++w)
        threads.emplace_back([&, w] {
            try {
                work(w);
            } catch (...) {
                failures[w] = std::current_exception();
            }
        });
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
}

TileShare renderTilesOnWorkers(const std::vector<TileRenderer*>& workers, const std::vector<PixelRect>& tiles, Film& film) {
    // Every worker has read the film before any writes a tile into it.
    runOnWorkerThreads(workers.size(), [&](size_t w) { workers[w]->startFrame(film); });
    TileShare share;
    share.tilesByWorker.assign(workers.size(), 0);
    TileQueue queue(tiles.size());
    std::atomic<uint64_t> rays{0};
    std::atomic<bool> failed{false};
    runOnWorkerThreads(workers.size(), [&](size_t w) {
        try {
            for (int32_t i; !failed && (i = queue.take()) >= 0;) {
                rays += workers[w]->renderTile(tiles[size_t(i)], film);
                ++share.tilesByWorker[w];
            }
        } catch (...) {
            failed = true;   // the others stop at their next tile: the frame is lost anyway
            throw;
        }
    });
    share.rays = rays;
    return share;
}

} // namespace urbis
