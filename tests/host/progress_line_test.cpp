// The progress line of long commands: nothing for short work or when stderr is not a terminal;
// past the delay, the phase and the elapsed time, rewritten in place, and cleared at the end.
#include <gtest/gtest.h>

#include <algorithm>
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

// A phase names the user's files: its control characters are escaped (a scene named
// "t\e]0;PWNED\a.json" set the terminal's title through this line), and a long one is cut, so that
// the line rewritten in place never wraps.
TEST(ProgressLine, APhaseIsEscapedAndCut) {
    std::ostringstream out;
    {
        host::ProgressLine p("loading t\x1b]0;PWNED\x07.json", 0ms, out, true, 10ms);
        std::this_thread::sleep_for(40ms);
        p.phase("loading " + std::string(100000, 'x'));
        std::this_thread::sleep_for(40ms);
    }
    std::string s = out.str();
    EXPECT_NE(s.find("lightscatter: loading t\\u001b]0;PWNED\\u0007.json ("), std::string::npos)
        << s;
    // The line's own escape, "\r\033[K", is the only one written.
    for (size_t at; (at = s.find("\r\033[K")) != std::string::npos;) s.replace(at, 4, "\n");
    EXPECT_EQ(s.find('\x1b'), std::string::npos) << s;
    EXPECT_EQ(s.find('\x07'), std::string::npos) << s;
    size_t longest = 0;
    for (size_t at = 0, end; at < s.size(); at = end + 1) {
        end = std::min(s.find('\n', at), s.size());
        longest = std::max(longest, end - at);
    }
    EXPECT_LE(longest, 250u);
    EXPECT_NE(s.find("xxx... ("), std::string::npos);
}
