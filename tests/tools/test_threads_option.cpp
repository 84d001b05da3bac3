// --threads N (tools/cli/threads_option.h): the engines' thread count, and the default of the
// command's other parallel loops (metrics, modelers), which otherwise take every core.
#include <gtest/gtest.h>

#include <omp.h>

#include <CLI/CLI.hpp>

#include "tools/cli/threads_option.h"

TEST(ThreadsOption, SetsTheDefaultOfTheOtherParallelLoops) {
  const int before = omp_get_max_threads();
  for (const int n : {1, 3}) {
    CLI::App app;
    int threads = 0;
    qacc::addThreadsOption(&app, threads);
    const std::string arg = std::to_string(n);
    const char* argv[] = {"qacc", "--threads", arg.c_str()};
    app.parse(3, const_cast<char**>(argv));
    EXPECT_EQ(threads, n);
    EXPECT_EQ(omp_get_max_threads(), n);
    int inLoop = 0;
#pragma omp parallel
    {
#pragma omp single
      inLoop = omp_get_num_threads();
    }
    EXPECT_EQ(inLoop, n) << "a parallel loop without num_threads";
  }
  // A refused value changes nothing.
  omp_set_num_threads(before);
  CLI::App app;
  int threads = 0;
  qacc::addThreadsOption(&app, threads);
  const char* argv[] = {"qacc", "--threads", "0"};
  EXPECT_THROW(app.parse(3, const_cast<char**>(argv)), CLI::ValidationError);
  EXPECT_EQ(omp_get_max_threads(), before);
}
