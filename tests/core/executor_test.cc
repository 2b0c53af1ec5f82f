#include "core/executor.h"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(Executor, ATaskGivesItsResultWithAndWithoutWorkers) {
  for (int workers : {0, 1, 3}) {
    Executor executor(workers);
    Task<int> task = executor.Submit([] { return 6 * 7; });
    ASSERT_TRUE(task.valid());
    EXPECT_EQ(task.Get(), 42) << workers << " workers";
    EXPECT_FALSE(task.valid());
  }
}

TEST(Executor, WithoutWorkersTasksRunOnTheCallerInTheOrderTheyAreGot) {
  Executor executor(0);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<int> order;
  Task<std::thread::id> first = executor.Submit([&] {
    order.push_back(1);
    return std::this_thread::get_id();
  });
  Task<std::thread::id> second = executor.Submit([&] {
    order.push_back(2);
    return std::this_thread::get_id();
  });
  EXPECT_TRUE(order.empty());  // nothing runs before it is asked for
  EXPECT_EQ(second.Get(), caller);
  EXPECT_EQ(first.Get(), caller);
  EXPECT_EQ(order, (std::vector<int>{2, 1}));
}

TEST(Executor, ATaskWaitingForAnotherNeverDeadlocksEvenWithOneWorker) {
  // The one worker runs the outer task, which waits for an inner task queued behind it: the
  // inner one is run by the waiting thread itself.
  Executor executor(1);
  Task<int> outer = executor.Submit([&executor] {
    Task<int> inner = executor.Submit([] { return 5; });
    return inner.Get() + 1;
  });
  EXPECT_EQ(outer.Get(), 6);
}

TEST(Executor, ATasksErrorReachesWhoeverGetsIt) {
  for (int workers : {0, 2}) {
    Executor executor(workers);
    Task<int> task = executor.Submit([]() -> int { throw std::runtime_error("broken input"); });
    EXPECT_THROW(task.Get(), std::runtime_error) << workers << " workers";
  }
}

TEST(Executor, WorkersRunTasksBesideTheCaller) {
  // Two tasks that each wait for the other to have started can only finish when they run at
  // the same time: on two workers.
  Executor executor(2);
  std::atomic<int> started{0};
  const auto rendezvous = [&started] {
    ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (started.load() < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    return started.load();
  };
  Task<int> a = executor.Submit(rendezvous);
  Task<int> b = executor.Submit(rendezvous);
  EXPECT_EQ(a.Get(), 2);
  EXPECT_EQ(b.Get(), 2);
}

TEST(Executor, ADroppedTaskThatNeverStartedNeverRuns) {
  Executor executor(0);
  bool ran = false;
  {
    Task<void> task = executor.Submit([&ran] { ran = true; });
  }
  EXPECT_FALSE(ran);
}

TEST(Executor, ParallelForCoversEveryIndexOnceAndRethrowsTheFirstError) {
  for (int workers : {0, 1, 3}) {
    Executor executor(workers);
    std::vector<std::atomic<int>> hits(100);
    executor.ParallelFor(100, [&hits](int i) { ++hits[static_cast<size_t>(i)]; });
    for (size_t i = 0; i < hits.size(); ++i) EXPECT_EQ(hits[i].load(), 1) << "index " << i;
    std::atomic<int> ran{0};
    EXPECT_THROW(executor.ParallelFor(10,
                                      [&ran](int i) {
                                        ++ran;
                                        if (i == 3) throw std::invalid_argument("index 3");
                                      }),
                 std::invalid_argument);
    EXPECT_EQ(ran.load(), 10);  // every index ran although one failed
  }
}

TEST(Executor, DefaultThreadsIsAtLeastOne) { EXPECT_GE(Executor::DefaultThreads(), 1); }

}  // namespace
}  // namespace dynvo
