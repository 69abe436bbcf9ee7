#include "cairn/common/parallel_for.h"

#include <algorithm>
#include <climits>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cairn/common/number_text.h"

namespace cairn {
namespace {

// One call's bands. Lives on the caller's stack; the pool touches it only under its mutex or while one of its
// bands is unfinished, and the caller returns only once every band has finished (which it sees under the mutex).
struct Job {
  const ParallelBandBody* body{nullptr};
  int count{0};
  int bands{0};
  // Guarded by the pool's mutex.
  int max_workers{0};  // pool threads that may work on it at once: the caller's thread count minus the caller
  int workers{0};      // pool threads working on it now
  int next{0};         // the next band to start
  int finished{0};
  int failed_band{INT_MAX};
  std::exception_ptr failure;
};

// True while this thread runs a band: a ParallelFor from inside a band runs inline instead of waiting for the
// pool (whose threads may all be busy with the outer bands).
thread_local bool t_inside_band = false;

// Runs one band, catching what it throws so that the other bands still run.
std::exception_ptr RunBand(const Job& job, int band) {
  const int begin = static_cast<int>(static_cast<std::int64_t>(job.count) * band / job.bands);
  const int end = static_cast<int>(static_cast<std::int64_t>(job.count) * (band + 1) / job.bands);
  const bool outer = t_inside_band;
  t_inside_band = true;
  std::exception_ptr failure;
  try {
    (*job.body)(band, begin, end);
  } catch (...) {
    failure = std::current_exception();
  }
  t_inside_band = outer;
  return failure;
}

// Threads started once and reused by every call; each call's bands are shared by its caller and up to
// (threads - 1) pool threads.
class WorkerPool {
 public:
  // Never destroyed: worker threads wait on its members until the process ends, and a ParallelFor may run from a
  // static destructor, after a function-local static pool would have been destroyed.
  static WorkerPool& Instance() {
    static WorkerPool* const pool = new WorkerPool();
    return *pool;
  }

  void Run(Job* job, int threads) {
    std::unique_lock<std::mutex> lock(mutex_);
    job->max_workers = std::min(job->bands, threads) - 1;
    StartWorkers(job->max_workers);
    queue_.push_back(job);
    for (int k = 0; k < job->max_workers; ++k) work_.notify_one();
    // The caller works too, so its bands finish even when every pool thread is busy with other calls.
    WorkOn(job, lock);
    done_.wait(lock, [job] { return job->finished == job->bands; });
  }

 private:
  WorkerPool() = default;

  // Grows the pool to `wanted` threads; it never shrinks. A thread the system refuses to start costs only speed:
  // the caller runs the bands that no pool thread takes.
  void StartWorkers(int wanted) {
    while (static_cast<int>(workers_.size()) < wanted) {
      try {
        workers_.emplace_back([this] { WorkerLoop(); });
      } catch (const std::system_error&) {
        return;
      }
    }
  }

  // Runs the job's bands until none is left to start. `lock` holds the mutex on entry and on return.
  void WorkOn(Job* job, std::unique_lock<std::mutex>& lock) {
    while (job->next < job->bands) {
      const int band = job->next++;
      if (job->next == job->bands) queue_.erase(std::find(queue_.begin(), queue_.end(), job));
      lock.unlock();
      std::exception_ptr failure = RunBand(*job, band);
      lock.lock();
      if (failure && band < job->failed_band) {
        job->failed_band = band;
        job->failure = std::move(failure);
      }
      if (++job->finished == job->bands) done_.notify_all();
    }
  }

  // The oldest queued job that may take another pool thread, or nullptr. Needs the mutex.
  Job* FindWork() const {
    for (Job* job : queue_) {
      if (job->workers < job->max_workers) return job;
    }
    return nullptr;
  }

  void WorkerLoop() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      Job* job = nullptr;
      work_.wait(lock, [this, &job] { return (job = FindWork()) != nullptr; });
      ++job->workers;
      WorkOn(job, lock);
      --job->workers;  // still under the mutex, so the job's caller has not returned yet
    }
  }

  std::mutex mutex_;
  std::condition_variable work_;
  std::condition_variable done_;
  std::deque<Job*> queue_;  // jobs with bands not yet started, oldest first
  std::vector<std::thread> workers_;
};

}  // namespace

int ResolveThreadCount(int num_threads) {
  if (num_threads < 0) {
    throw std::invalid_argument("num_threads " + FormatShort(num_threads) +
                                " is negative; use 0 for one thread per core, or a positive count");
  }
  if (num_threads > kMaxThreads) {
    throw std::invalid_argument("num_threads " + FormatShort(num_threads) + " is above the limit of " +
                                FormatShort(kMaxThreads) + "; use 0 for one thread per core, or at most " +
                                FormatShort(kMaxThreads));
  }
  if (num_threads > 0) return num_threads;
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores, 1, kMaxThreads);
}

void ParallelFor(int count, int num_threads, const ParallelBandBody& body) {
  const int threads = ResolveThreadCount(num_threads);
  if (count < 0) throw std::invalid_argument("ParallelFor: count " + FormatShort(count) + " is negative");
  if (count == 0) return;
  ParallelForBands(count, std::min(threads, count), threads, body);
}

void ParallelForBands(int count, int num_bands, int num_threads, const ParallelBandBody& body) {
  const int threads = ResolveThreadCount(num_threads);
  if (count < 0) throw std::invalid_argument("ParallelForBands: count " + FormatShort(count) + " is negative");
  if (num_bands < 1) {
    throw std::invalid_argument("ParallelForBands: num_bands " + FormatShort(num_bands) + " must be at least 1");
  }
  Job job;
  job.body = &body;
  job.count = count;
  job.bands = num_bands;
  if (threads == 1 || num_bands == 1 || t_inside_band) {
    for (int band = 0; band < num_bands; ++band) {
      std::exception_ptr failure = RunBand(job, band);
      if (failure && !job.failure) job.failure = std::move(failure);
    }
  } else {
    WorkerPool::Instance().Run(&job, threads);
  }
  if (job.failure) std::rethrow_exception(job.failure);
}

}  // namespace cairn
