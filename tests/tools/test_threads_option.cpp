// --threads N (tools/cli/threads_option.h): the engines' thread count, and the default of the
// command's other parallel loops (metrics, modelers), which otherwise take every core.
#include <gtest/gtest.h>

#include <omp.h>

#include <CLI/CLI.hpp>
#include <string>

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
  // In a subcommand (as qacc's commands are), the default is set before its callback runs the
  // command; the value is read as CLI11 reads it (010 is octal).
  for (const char* text : {"3", "010"}) {
    CLI::App app;
    CLI::App* sub = app.add_subcommand("render");
    int threads = 0, seen = 0;
    qacc::addThreadsOption(sub, threads);
    sub->callback([&] { seen = omp_get_max_threads(); });
    const char* argv[] = {"qacc", "render", "--threads", text};
    app.parse(4, const_cast<char**>(argv));
    EXPECT_EQ(seen, threads) << text;
    EXPECT_EQ(threads, std::string(text) == "3" ? 3 : 8) << text;
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
