#pragma once
// Scratch objects lent to whichever thread asks and returned when the lease
// ends, so large buffers keep their memory from one use to the next.
// Thread-local storage would not: OpenMP starts new threads for every nested
// parallel region (a diagnosis runs its candidates' fits inside one), and a
// buffer that dies with its thread costs its page faults again on the next.
// The contents of a leased object are whatever its last user left.
#include <memory>
#include <mutex>
#include <vector>

namespace hystbench {

template <class T>
class ScratchPool {
 public:
  struct GiveBack {
    ScratchPool* pool;
    void operator()(T* object) const { pool->give_back(object); }
  };
  using Lease = std::unique_ptr<T, GiveBack>;

  Lease lend() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (idle_.empty()) return Lease(new T(), GiveBack{this});
    T* object = idle_.back().release();
    idle_.pop_back();
    return Lease(object, GiveBack{this});
  }

 private:
  void give_back(T* object) {
    std::unique_ptr<T> owned(object);
    std::lock_guard<std::mutex> lock(mutex_);
    idle_.push_back(std::move(owned));
  }

  std::mutex mutex_;
  std::vector<std::unique_ptr<T>> idle_;
};

}  // namespace hystbench
