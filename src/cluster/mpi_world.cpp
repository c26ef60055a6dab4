// The MPI build: MPI_COMM_WORLD membership and the tile queue (mpi_world.h). MPI is confined to this file.
#include "cluster/mpi_world.h"

#include "base/input_error.h"
#include "cluster/film_tiles.h"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <thread>

namespace urbis {

namespace {

/// Message tags: a worker's first request (empty), rank 0's answer (a tile index, -1: no more),
/// a worker's finished tile (TileHeader, then the tile's film bytes).
enum Tag : int { kReady = 1, kAssign = 2, kResult = 3 };

struct TileHeader {
    int32_t tile;
    uint64_t rays;
};

/// The test hook of tests/mpi_render_test.cpp: URBIS_TEST_KILL_RANK=R kills rank R (SIGKILL, as a
/// crashed or preempted node would end) at rank 0's first answer: mid-frame, or, where rank 0 has
/// rendered every tile before R asked, before the closing barrier, which rank 0 then never passes.
void dieIfTestAsks(int rank) {
    const char* victim = std::getenv("URBIS_TEST_KILL_RANK");
    if (victim && std::atoi(victim) == rank) std::raise(SIGKILL);
}

void check(int status, const char* call) {
    if (status != MPI_SUCCESS) throw InputError(std::string("MPI call failed: ") + call, FailureKind::Device);
}

/// Rank 0: answers requests and collects tiles until every other rank has been told there are no
/// more, while a second thread renders tiles from the same queue.
TileShare serveTiles(const MpiWorld& world, const std::vector<PixelRect>& tiles, Film& film, TileRenderer& renderer) {
    TileShare share;
    share.tilesByWorker.assign(size_t(world.ranks()), 0);
    TileQueue queue(tiles.size());
    std::atomic<uint64_t> localRays{0};
    std::exception_ptr localFailure;
    std::thread local([&] {
        try {
            for (int32_t i; (i = queue.take()) >= 0;) {
                localRays += renderer.renderTile(tiles[size_t(i)], film);
                ++share.tilesByWorker[0];
            }
        } catch (...) {
            localFailure = std::current_exception();
        }
    });
    std::vector<uint8_t> message;
    for (int working = world.ranks() - 1; working > 0;) {
        int arrived = 0;
        MPI_Status status;
        check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status), "MPI_Iprobe");
        if (!arrived) {
            // Polled rather than blocked on: Open MPI's blocking receive spins a core that this rank's
            // own tiles need.
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        message.resize(size_t(bytes));
        check(MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                       MPI_STATUS_IGNORE), "MPI_Recv");
        if (status.MPI_TAG == kResult) {
            TileHeader header;
            std::memcpy(&header, message.data(), sizeof header);
            message.erase(message.begin(), message.begin() + sizeof header);
            unpackFilmRect(message, tiles.at(size_t(header.tile)), film);
            share.rays += header.rays;
            ++share.tilesByWorker[size_t(status.MPI_SOURCE)];
        }
        const int32_t assigned = queue.take();
        check(MPI_Send(&assigned, 1, MPI_INT32_T, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD), "MPI_Send");
        if (assigned < 0) --working;
    }
    local.join();
    if (localFailure) std::rethrow_exception(localFailure);
    share.rays += localRays;
    return share;
}

/// Ranks 1..N-1: ask, render, send back, until rank 0 answers -1.
void workOnTiles(const MpiWorld& world, const std::vector<PixelRect>& tiles, Film& film, TileRenderer& renderer) {
    check(MPI_Send(nullptr, 0, MPI_BYTE, 0, kReady, MPI_COMM_WORLD), "MPI_Send");
    std::vector<uint8_t> message;
    for (;;) {
        int32_t tile = -1;
        check(MPI_Recv(&tile, 1, MPI_INT32_T, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
        dieIfTestAsks(world.rank());
        if (tile < 0) return;
        const TileHeader header{tile, renderer.renderTile(tiles.at(size_t(tile)), film)};
        const std::vector<uint8_t> pixels = packFilmRect(film, tiles[size_t(tile)]);
        message.resize(sizeof header + pixels.size());
        std::memcpy(message.data(), &header, sizeof header);
        std::memcpy(message.data() + sizeof header, pixels.data(), pixels.size());
        check(MPI_Send(message.data(), int(message.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD), "MPI_Send");
    }
}

} // namespace

MpiWorld::MpiWorld() {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    MPI_Comm local;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &local);
    MPI_Comm_rank(local, &localRank_);
    MPI_Comm_free(&local);
}

MpiWorld::~MpiWorld() { MPI_Finalize(); }

void MpiWorld::barrier() const { MPI_Barrier(MPI_COMM_WORLD); }

void MpiWorld::broadcastFilm(Film& film) const {
    forEachFilmArray(
        [](auto, bool, auto& array) {
            // In pieces of at most 1 GiB: MPI counts in int.
            auto* bytes = reinterpret_cast<uint8_t*>(array.data());
            const size_t total = array.size() * sizeof(array[0]);
            for (size_t at = 0; at < total; at += size_t(1) << 30) {
                const int count = int(std::min(total - at, size_t(1) << 30));
                check(MPI_Bcast(bytes + at, count, MPI_BYTE, 0, MPI_COMM_WORLD), "MPI_Bcast");
            }
        },
        film.arrays);
}

void MpiWorld::abort(int exitCode) const {
    MPI_Abort(MPI_COMM_WORLD, exitCode);
    std::_Exit(exitCode);  // MPI_Abort does not return; this says so to the compiler
}

TileShare renderTilesAcrossRanks(const MpiWorld& world, const std::vector<PixelRect>& tiles, Film& film,
                                 TileRenderer& renderer) {
    renderer.startFrame(film);
    TileShare share;
    if (world.isRoot()) share = serveTiles(world, tiles, film, renderer);
    else workOnTiles(world, tiles, film, renderer);
    // Rank 0 writes only once every rank is known to be alive at the end: a rank that died anywhere
    // before leaves rank 0 here until mpirun ends the job.
    check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
    return share;
}

} // namespace urbis
