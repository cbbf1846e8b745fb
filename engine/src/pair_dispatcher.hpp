#pragma once
// Bullet's collision dispatcher with the narrowphase of a step spread over several threads.
// Private to the engine.
//
// Debian's Bullet is built without BT_THREADSAFE, so btDiscreteDynamicsWorldMt and its task
// schedulers run serially. Collision detection is most of a dense pile's step (a 500-cube heap:
// 56 % in the narrowphase, 37 % in the solver), and every broadphase pair's query touches only
// its own collision algorithm and contact manifolds: the pairs can run at once. What they share
// is the dispatcher: its pools (algorithms and manifolds) and its array of manifolds, whose
// order is the order in which the solver meets the contacts. This dispatcher locks the pools,
// and instead of letting the threads append and remove manifolds in whatever order they run, it
// logs each creation and release with the pair that made it and replays the log in pair order
// after the pairs are done: the array ends exactly as one thread leaves it, so a run is
// bit-identical whatever the thread count (tests/engine/test_pair_dispatcher.cpp).

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <mutex>
#include <vector>

namespace rockfall::shapes {
class ThreadPool;
}

namespace rockfall::engine {

class PairDispatcher : public btCollisionDispatcher {
  public:
    explicit PairDispatcher(btCollisionConfiguration* configuration);
    ~PairDispatcher() override;
    PairDispatcher(const PairDispatcher&) = delete;
    PairDispatcher& operator=(const PairDispatcher&) = delete;

    // Threads for a step's pairs (>= 1; 1, the default: the caller's thread alone).
    void set_threads(int threads);
    int threads() const;

    void dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                   btDispatcher* dispatcher) override;
    btPersistentManifold* getNewManifold(const btCollisionObject* body0,
                                         const btCollisionObject* body1) override;
    void releaseManifold(btPersistentManifold* manifold) override;
    void* allocateCollisionAlgorithm(int size) override;
    void freeCollisionAlgorithm(void* memory) override;

  private:
    // A manifold made or released while processing pair `pair`, its `sequence`-th such event.
    struct Event {
        int pair = 0;
        int sequence = 0;
        bool created = false;
        btPersistentManifold* manifold = nullptr;
    };

    void replay_events();

    std::unique_ptr<shapes::ThreadPool> workers_;
    bool concurrent_ = false;  // true while the pairs run on several threads
    std::mutex mutex_;         // the pools, and the event log while concurrent_
    std::vector<Event> events_;
    int manifolds_before_ = 0;  // manifolds in the array when the pairs started
};

}  // namespace rockfall::engine
