// Subcommands of the qacc command line; each lives in its own file and registers itself
// on the application (see qacc_main.cpp).
#pragma once
#include <CLI/CLI.hpp>

namespace qacc {

void addRenderCommand(CLI::App& app);
void addBatchCommand(CLI::App& app);
void addInfoCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);  // tools/compare_command.cpp
void addReduceCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);  // tools/bench_command.cpp (accelerator benchmark)
void addBenchLoadCommand(CLI::App& app);  // tools/bench_load_command.cpp (loading benchmark)
void addSweepCommand(CLI::App& app);
void addAutosizeCommand(CLI::App& app);

}  // namespace qacc
