#pragma once
// The lightscatter command line's commands (a contract: see docs/host_example.md). Each returns the
// exit code and throws std::exception with one line for any failure.
#include "cli_args.h"

namespace host {

int runRender(Args& args);
int runBudget(Args& args);
int runGraph(Args& args);
int runView(Args& args);
int runPattern(Args& args);
int runBench(Args& args);

}  // namespace host
