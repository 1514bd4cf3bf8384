#include "ossa/game/herd.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "ossa/assert.h"

namespace ossa {

std::shared_ptr<const AnimRig> RigCache::rig(const std::shared_ptr<const Creature>& creature) {
  OSSA_ASSERT(creature != nullptr, "RigCache::rig: no creature");
  auto it = rigs_.find(creature.get());
  if (it != rigs_.end()) return it->second.rig;
  // A miss first forgets the rigs no entity holds any more (a creature swapped out in the
  // editor), so the cache stays as large as the set of creatures in use.
  std::erase_if(rigs_, [](const auto& kv) { return kv.second.rig.use_count() == 1; });
  it = rigs_.emplace(creature.get(), Entry{creature, build_anim_rig(*creature)}).first;
  return it->second.rig;
}

int resolve_threads(int threads) { return threads > 0 ? threads : tbb::info::default_concurrency(); }

namespace {
constexpr size_t kPrefetchObject = 2, kPrefetchState = 1;
}  // namespace

void step_all(std::span<Entity* const> entities, std::span<const Controls> controls, float dt, const Level& level,
              int threads) {
  OSSA_ASSERT(entities.size() == controls.size(), "step_all: one Controls per entity");
  const size_t n = entities.size();
  const int t = resolve_threads(threads);
  // A creature's state is cold by its next tick in a large herd: each step first asks for the
  // state of the creatures a few places ahead (Animator::prefetch).
  auto step = [&](size_t i, size_t end) {
    if (i + kPrefetchObject < end) entities[i + kPrefetchObject]->animator().prefetch(true);
    if (i + kPrefetchState < end) entities[i + kPrefetchState]->animator().prefetch(false);
    entities[i]->step(dt, controls[i], level);
  };
  if (t == 1 || n < 2) {
    for (size_t i = 0; i < n; ++i) step(i, n);
    return;
  }
  // Chunks of a few creatures (a creature's step is a few microseconds): enough chunks to
  // balance, few enough that scheduling costs nothing next to the work.
  tbb::task_arena arena(t);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 8), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) step(i, r.end());
    });
  });
}

}  // namespace ossa
