#pragma once
// The one place dynvo runs work concurrently: a fixed pool of worker threads fed by a queue of
// tasks. A task is run once, by a worker or, when nobody has started it yet, by the thread that
// waits for it, so a task may wait for another without deadlock and a pool of no workers runs
// everything in order on the caller. Results never depend on which thread ran a task.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace dynvo {

namespace internal {

// What the queue holds: a job that runs once, whoever claims it first.
class ClaimableJob {
 public:
  virtual ~ClaimableJob() = default;
  // Runs the job unless it was claimed before; true when this call ran it.
  bool RunIfUnclaimed() {
    if (claimed_.exchange(true)) return false;
    Run();
    return true;
  }
  // Claims the job without running it (it never runs); true when nobody had claimed it.
  bool Cancel() { return !claimed_.exchange(true); }

 private:
  virtual void Run() = 0;
  std::atomic<bool> claimed_{false};
};

template <typename T>
class PackagedJob : public ClaimableJob {
 public:
  explicit PackagedJob(std::function<T()> work) : task_(std::move(work)), future_(task_.get_future()) {}
  std::future<T>& future() { return future_; }

 private:
  void Run() override { task_(); }
  std::packaged_task<T()> task_;
  std::future<T> future_;
};

}  // namespace internal

// A submitted task's result. Move-only. Destroying a task that no thread has started cancels
// it; destroying a started one waits for it to finish.
template <typename T>
class Task {
 public:
  Task() = default;
  explicit Task(std::shared_ptr<internal::PackagedJob<T>> job) : job_(std::move(job)) {}
  Task(Task&&) noexcept = default;
  Task& operator=(Task&& other) noexcept {
    Reset();
    job_ = std::move(other.job_);
    return *this;
  }
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  ~Task() { Reset(); }

  // True until Get() or Reset().
  bool valid() const { return job_ != nullptr; }
  // The task's result: runs it on this thread when no worker has started it, else waits for
  // it. Rethrows what the task threw. The task is no longer valid afterwards.
  T Get() {
    std::shared_ptr<internal::PackagedJob<T>> job = std::move(job_);
    job->RunIfUnclaimed();
    return job->future().get();
  }
  // Waits at most `timeout` for the task to finish; true when it has (Get then returns at once).
  // Needs a valid task. A task that no worker has started may not start in time.
  template <typename Rep, typename Period>
  bool WaitFor(const std::chrono::duration<Rep, Period>& timeout) const {
    return job_->future().wait_for(timeout) == std::future_status::ready;
  }
  // Cancels the task when not started, else waits for it, dropping its result or error.
  void Reset() {
    if (!job_) return;
    if (!job_->Cancel()) job_->future().wait();
    job_.reset();
  }

 private:
  std::shared_ptr<internal::PackagedJob<T>> job_;
};

class Executor {
 public:
  // A pool of `num_workers` threads (>= 0; 0 = every task runs on the thread that gets it).
  explicit Executor(int num_workers);
  // Runs the tasks still queued, then joins the workers.
  ~Executor();
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  // Queues `work` (a callable taking no arguments) and returns its result's handle.
  template <typename F>
  Task<std::invoke_result_t<F>> Submit(F&& work) {
    using T = std::invoke_result_t<F>;
    auto job = std::make_shared<internal::PackagedJob<T>>(std::function<T()>(std::forward<F>(work)));
    if (!workers_.empty()) Enqueue(job);
    return Task<T>(std::move(job));
  }

  // Runs `body(i)` for every i in [0, count), on the workers and this thread, and returns when
  // all are done; rethrows the first error (by index) after all have finished.
  void ParallelFor(int count, const std::function<void(int)>& body);

  int num_workers() const { return static_cast<int>(workers_.size()); }
  // The threads a run uses by default: the machine's cores (at least 1).
  static int DefaultThreads();

 private:
  void Enqueue(std::shared_ptr<internal::ClaimableJob> job);
  void WorkerLoop();

  std::mutex mutex_;
  std::condition_variable queued_;
  std::deque<std::shared_ptr<internal::ClaimableJob>> queue_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace dynvo
