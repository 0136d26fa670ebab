// The progress line of long commands: nothing for short work or when stderr is not a terminal;
// past the delay, the phase and the elapsed time, rewritten in place, and cleared at the end.
#include <gtest/gtest.h>

#include <sstream>
#include <thread>

#include "progress_line.h"

using namespace std::chrono_literals;

TEST(ProgressLine, LongWorkShowsItsPhaseAndTimeThenClearsTheLine) {
    std::ostringstream out;
    {
        host::ProgressLine p("loading", 20ms, out, true, 10ms);
        std::this_thread::sleep_for(60ms);
        p.phase("writing x.png");
        std::this_thread::sleep_for(60ms);
    }
    const std::string s = out.str();
    EXPECT_NE(s.find("\r\033[Klightscatter: loading ("), std::string::npos) << s;
    EXPECT_NE(s.find("\r\033[Klightscatter: writing x.png ("), std::string::npos) << s;
    EXPECT_NE(s.find(" s)"), std::string::npos) << s;
    EXPECT_EQ(s.substr(s.size() - 4), "\r\033[K");  // nothing left on the line
}

TEST(ProgressLine, ShortWorkShowsNothing) {
    std::ostringstream out;
    { host::ProgressLine p("loading", 2000ms, out, true, 10ms); }
    EXPECT_EQ(out.str(), "");
}

TEST(ProgressLine, NothingWhenStderrIsNotATerminal) {
    std::ostringstream out;
    {
        host::ProgressLine p("loading", 0ms, out, false, 10ms);
        std::this_thread::sleep_for(40ms);
    }
    EXPECT_EQ(out.str(), "");
}
