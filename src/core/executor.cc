#include "core/executor.h"

#include <exception>

namespace dynvo {

Executor::Executor(int num_workers) {
  for (int i = 0; i < num_workers; ++i) workers_.emplace_back([this] { WorkerLoop(); });
}

Executor::~Executor() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void Executor::Enqueue(std::shared_ptr<internal::ClaimableJob> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(job));
  }
  queued_.notify_one();
}

void Executor::WorkerLoop() {
  for (;;) {
    std::shared_ptr<internal::ClaimableJob> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      queued_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    job->RunIfUnclaimed();  // a task's exception stays in its future
  }
}

void Executor::ParallelFor(int count, const std::function<void(int)>& body) {
  std::vector<Task<void>> tasks;
  tasks.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) tasks.push_back(Submit([&body, i] { body(i); }));
  std::exception_ptr first_error;
  for (Task<void>& task : tasks) {
    try {
      task.Get();
    } catch (...) {
      if (!first_error) first_error = std::current_exception();
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

int Executor::DefaultThreads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(cores);
}

}  // namespace dynvo
