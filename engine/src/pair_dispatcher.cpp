#include "pair_dispatcher.hpp"

#include "shapes/thread_pool.hpp"

#include <algorithm>
#include <cassert>
#include <tuple>

namespace rockfall::engine {
namespace {

// Below this many broadphase pairs a step runs on the caller's thread alone: waking the
// workers costs more than the pairs (a single rock on the slope has a few dozen).
constexpr int kMinConcurrentPairs = 64;
// Pairs per task: a task is a few microseconds of GJK, well above the cost of claiming it.
constexpr int kPairsPerTask = 16;

// The pair a thread is processing, and how many manifold events it has made so far.
struct PairContext {
    int pair = 0;
    int sequence = 0;
};
thread_local PairContext t_context;

}  // namespace

PairDispatcher::PairDispatcher(btCollisionConfiguration* configuration)
    : btCollisionDispatcher(configuration) {}

PairDispatcher::~PairDispatcher() = default;

void PairDispatcher::set_threads(int threads) {
    assert(threads >= 1);
    if (threads == this->threads()) return;
    workers_ = threads > 1 ? std::make_unique<shapes::ThreadPool>(threads) : nullptr;
}

int PairDispatcher::threads() const { return workers_ ? workers_->size() : 1; }

void PairDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* pairs,
                                               const btDispatcherInfo& info,
                                               btDispatcher* dispatcher) {
    const int count = pairs->getNumOverlappingPairs();
    // Sorted pairs (m_deterministicOverlappingPairs) are Bullet's own serial path.
    if (!workers_ || count < kMinConcurrentPairs || info.m_deterministicOverlappingPairs) {
        btCollisionDispatcher::dispatchAllCollisionPairs(pairs, info, dispatcher);
        return;
    }
    // Bullet's serial dispatch calls the near callback for every pair in array order (its
    // pair callback never removes a pair); so do the tasks, each on its own pairs.
    btBroadphasePair* pair = pairs->getOverlappingPairArrayPtr();
    const btNearCallback near_callback = getNearCallback();
    manifolds_before_ = m_manifoldsPtr.size();
    events_.clear();
    concurrent_ = true;
    workers_->parallel_for(count, kPairsPerTask, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            t_context = {i, 0};
            near_callback(pair[i], *this, info);
        }
    });
    concurrent_ = false;
    replay_events();
}

btPersistentManifold* PairDispatcher::getNewManifold(const btCollisionObject* body0,
                                                     const btCollisionObject* body1) {
    if (!concurrent_) return btCollisionDispatcher::getNewManifold(body0, body1);
    const std::lock_guard<std::mutex> lock(mutex_);
    // Bullet's own creation (pool, thresholds), appended to the array after the manifolds that
    // were there before the pairs; the replay redoes its place.
    btPersistentManifold* manifold = btCollisionDispatcher::getNewManifold(body0, body1);
    events_.push_back({t_context.pair, t_context.sequence++, true, manifold});
    return manifold;
}

void PairDispatcher::releaseManifold(btPersistentManifold* manifold) {
    if (!concurrent_) {
        btCollisionDispatcher::releaseManifold(manifold);
        return;
    }
    // Emptied now as Bullet does; taken out of the array and freed by the replay.
    clearManifold(manifold);
    const std::lock_guard<std::mutex> lock(mutex_);
    events_.push_back({t_context.pair, t_context.sequence++, false, manifold});
}

// The algorithm pool is locked always: uncontended outside the concurrent pairs, and rare.
void* PairDispatcher::allocateCollisionAlgorithm(int size) {
    const std::lock_guard<std::mutex> lock(mutex_);
    return btCollisionDispatcher::allocateCollisionAlgorithm(size);
}

void PairDispatcher::freeCollisionAlgorithm(void* memory) {
    const std::lock_guard<std::mutex> lock(mutex_);
    btCollisionDispatcher::freeCollisionAlgorithm(memory);
}

// The manifold array as the serial dispatch leaves it: the array before the pairs (its first
// manifolds_before_ entries, untouched: creations only appended and releases were deferred),
// then each pair's events in pair order, a creation appended at the end, a release swapped with the
// last manifold and removed (Bullet's btCollisionDispatcher::getNewManifold and
// releaseManifold). A released manifold stays allocated until here, so no later creation
// reuses its address during the pairs.
void PairDispatcher::replay_events() {
    std::sort(events_.begin(), events_.end(), [](const Event& a, const Event& b) {
        return std::tie(a.pair, a.sequence) < std::tie(b.pair, b.sequence);
    });
    m_manifoldsPtr.resize(manifolds_before_);
    std::vector<btPersistentManifold*> released;
    for (const Event& event : events_) {
        btPersistentManifold* manifold = event.manifold;
        if (event.created) {
            manifold->m_index1a = m_manifoldsPtr.size();
            m_manifoldsPtr.push_back(manifold);
            continue;
        }
        const int at = manifold->m_index1a;
        const int last = m_manifoldsPtr.size() - 1;
        assert(at >= 0 && at <= last && m_manifoldsPtr[at] == manifold);
        m_manifoldsPtr.swap(at, last);
        m_manifoldsPtr[at]->m_index1a = at;
        m_manifoldsPtr.pop_back();
        released.push_back(manifold);
    }
    // Freed by Bullet's release, each from the end of the array where nothing moves.
    for (btPersistentManifold* manifold : released) {
        manifold->m_index1a = m_manifoldsPtr.size();
        m_manifoldsPtr.push_back(manifold);
        btCollisionDispatcher::releaseManifold(manifold);
    }
}

}  // namespace rockfall::engine
