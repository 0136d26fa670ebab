#include "terminal_text.h"

namespace host {

std::string terminalText(const std::string& text, size_t limit) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (size_t i = 0; i < text.size() && out.size() <= limit; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        // C1 controls (U+0080 to U+009F, 0xC2 0x80-0x9F in UTF-8): some terminals act on them
        // as on ESC [ and the like.
        const bool c1 = c == 0xC2 && i + 1 < text.size() &&
                        (static_cast<unsigned char>(text[i + 1]) & 0xE0) == 0x80;
        if (c1) {
            const auto d = static_cast<unsigned char>(text[++i]);
            out += std::string("\\u00") + hex[d >> 4] + hex[d & 15];
        } else if (c >= 0x20 && c != 0x7F) {
            out += char(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            out += std::string("\\u00") + hex[c >> 4] + hex[c & 15];
        }
    }
    if (out.size() <= limit) return out;
    size_t keep = limit >= 3 ? limit - 3 : 0;
    while (keep > 0 && (static_cast<unsigned char>(out[keep]) & 0xC0) == 0x80) --keep;
    out.resize(keep);
    return out + "...";
}

}  // namespace host
