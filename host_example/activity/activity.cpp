#include "activity.h"

#include <exception>
#include <vector>

namespace host {
namespace {

// The activities are unwound by the exception before main() can ask what ran out, so the last
// one is remembered beyond its scope until another begins.
thread_local std::vector<std::string> stack;
thread_local std::string lastFailed;

}  // namespace

Activity::Activity(std::string what) {
    stack.push_back(std::move(what));
    lastFailed.clear();
}

Activity::~Activity() {
    if (std::uncaught_exceptions() > 0 && lastFailed.empty()) lastFailed.swap(stack.back());
    stack.pop_back();
}

const char* currentActivity() {
    if (!stack.empty()) return stack.back().c_str();
    return lastFailed.c_str();
}

}  // namespace host
