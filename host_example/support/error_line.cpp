#include "error_line.h"

#include "terminal_text.h"

namespace host {

std::string errorLine(const std::string& message) {
    std::string m = message;
    const std::string prefix = "lightscatter: ";
    while (m.rfind(prefix, 0) == 0) m.erase(0, prefix.size());
    std::string out;
    size_t start = 0;
    while (start <= m.size()) {
        size_t end = m.find('\n', start);
        if (end == std::string::npos) end = m.size();
        std::string line = m.substr(start, end - start);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
        start = end + 1;
    }
    return terminalText(out);
}

}  // namespace host
