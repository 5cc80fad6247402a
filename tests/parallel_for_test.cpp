// The jobs' one parallel loop (include/viscor/jobs/parallel_for.hpp): every index once,
// the lowest failing index kept, a stop by keep_going or by the poll.
#include <viscor/jobs/parallel_for.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace viscor::jobs {
namespace {

TEST(ParallelFor, CallsEveryIndexOnce) {
  for (const unsigned threads : {1u, 2u, 5u})
    for (const std::size_t block : {std::size_t{1}, std::size_t{7}})
      for (const bool with_poll : {false, true}) {
        std::vector<std::atomic<int>> calls(1000);
        parallel_for_options options;
        options.threads = threads, options.block = block;
        if (with_poll) options.poll = [] { return true; };
        const parallel_for_result r = parallel_for(calls.size(), [&](std::size_t i) { ++calls[i]; }, options);
        EXPECT_FALSE(r.failed());
        EXPECT_FALSE(r.stopped);
        for (std::size_t i = 0; i < calls.size(); ++i)
          ASSERT_EQ(calls[i], 1) << "index " << i << ", threads " << threads << ", block " << block;
      }
}

TEST(ParallelFor, NothingToDoIsNoFailure) {
  const parallel_for_result r = parallel_for(0, [](std::size_t) { throw std::runtime_error("called"); });
  EXPECT_FALSE(r.failed());
  EXPECT_FALSE(r.stopped);
}

// Indices are handed out in order, so the lower of two failing indices has always been
// called when the higher one fails: the lowest is the one kept, on any number of threads.
TEST(ParallelFor, KeepsTheLowestFailingIndex) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    parallel_for_options options;
    options.threads = threads;
    const parallel_for_result r = parallel_for(
        500,
        [](std::size_t i) {
          if (i == 40 || i == 41 || i == 300) throw std::runtime_error("index " + std::to_string(i));
        },
        options);
    ASSERT_TRUE(r.failed()) << threads;
    EXPECT_EQ(r.failed_at, 40u) << threads;
    try {
      std::rethrow_exception(r.failure);
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "index 40");
    }
  }
}

TEST(ParallelFor, KeepGoingStopsTheHandOut) {
  std::atomic<int> calls{0};
  parallel_for_options options;
  options.threads = 2;
  options.keep_going = [&] { return calls < 10; };
  const parallel_for_result r = parallel_for(1000, [&](std::size_t) { ++calls; }, options);
  EXPECT_TRUE(r.stopped);
  EXPECT_FALSE(r.failed());
  EXPECT_GE(calls, 10);
  EXPECT_LE(calls, 11);  // the other worker may have been past its check
}

TEST(ParallelFor, APollThatSaysStopStopsTheHandOut) {
  std::atomic<int> calls{0}, polls{0};
  parallel_for_options options;
  options.threads = 2;
  options.poll_interval = std::chrono::milliseconds(1);
  options.poll = [&] { return ++polls < 3; };
  const parallel_for_result r = parallel_for(
      1000000,
      [&](std::size_t) {
        ++calls;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      },
      options);
  EXPECT_TRUE(r.stopped);
  EXPECT_GE(polls, 3);
  EXPECT_LT(calls, 1000000);
}

}  // namespace
}  // namespace viscor::jobs
