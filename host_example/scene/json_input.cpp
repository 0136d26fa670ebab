#include "scene/json_input.h"

#include <set>
#include <vector>

#include "scene/input_file.h"

namespace host {
namespace {

using nlohmann::json;

// Cuts `text` to at most `limit` bytes, "..." included, without splitting a UTF-8 sequence.
std::string cut(std::string text, size_t limit) {
    if (text.size() <= limit) return text;
    size_t keep = limit >= 3 ? limit - 3 : 0;
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
    text.resize(keep);
    return text + "...";
}

// A string as a JSON string literal, from at most `limit` of its bytes (the caller cuts the rest).
std::string quoted(const std::string& s, size_t limit) {
    const json text = s.size() > limit ? s.substr(0, limit) : s;
    // replace: a cut in the middle of a UTF-8 sequence becomes U+FFFD instead of an exception.
    return text.dump(-1, ' ', false, json::error_handler_t::replace);
}

// Appends `v` as compact JSON until `out` holds more than `limit` bytes. The recursion is bounded
// by the depth the parser accepted.
void appendEcho(const json& v, std::string& out, size_t limit) {
    if (out.size() > limit) return;
    if (v.is_array()) {
        out += '[';
        for (size_t i = 0; i < v.size() && out.size() <= limit; ++i) {
            if (i) out += ',';
            appendEcho(v[i], out, limit);
        }
        out += ']';
    } else if (v.is_object()) {
        out += '{';
        for (auto it = v.begin(); it != v.end() && out.size() <= limit; ++it) {
            if (it != v.begin()) out += ',';
            out += quoted(it.key(), limit) + ':';
            appendEcho(it.value(), out, limit);
        }
        out += '}';
    } else if (v.is_string()) {
        out += quoted(v.get_ref<const std::string&>(), limit);
    } else {
        out += v.dump();  // numbers, booleans, null: short
    }
}

// nlohmann's messages quote the token that failed ("last read: '<token>'", "number overflow
// parsing '<token>'"), which can be a whole string or number of the file: the token is cut like any
// echoed value.
std::string shortenedReason(const std::string& what) {
    for (const std::string marker : {"last read: '", "parsing '"}) {
        const size_t open = what.find(marker);
        if (open == std::string::npos) continue;
        const size_t start = open + marker.size();
        // After the token comes "'" or "'; expected ...", which never holds "'; expected " again.
        size_t close = what.rfind("'; expected ");
        if (close == std::string::npos || close < start) close = what.rfind('\'');
        if (close == std::string::npos || close < start) break;
        return what.substr(0, start) + echoText(what.substr(start, close - start)) +
               cut(what.substr(close), 2 * kMaxEchoChars);
    }
    return cut(what, 4 * kMaxEchoChars);
}

// Follows the parser's events to know where it is ("camera.position[2]"), to cap the depth and to
// see repeated keys as they are read.
class ParseWatcher {
  public:
    ParseWatcher(const std::string& path, JsonRules rules) : path_(path), rules_(rules) {}

    bool operator()(int, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start:
                if (open_.size() >= kMaxJsonDepth) {
                    fail(where(open_.size()) + ": arrays and objects nest more than " +
                         std::to_string(kMaxJsonDepth) + " deep here (the most this reader takes)");
                }
                open_.push_back({event == json::parse_event_t::array_start, {}, 0, {}});
                break;
            case json::parse_event_t::key: {
                Level& object = open_.back();
                object.key = parsed.get_ref<const std::string&>();
                if (rules_.refuseDuplicateKeys && !object.keys.insert(object.key).second) {
                    const std::string in = where(open_.size() - 1);
                    fail((in.empty() ? "" : in + ": ") + "key '" + echoText(object.key) +
                         "' appears twice in one object");
                }
                break;
            }
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                open_.pop_back();
                nextElement();
                break;
            case json::parse_event_t::value:
                nextElement();
                break;
        }
        return true;
    }

  private:
    struct Level {
        bool array;
        std::string key;  // objects: the key being read
        size_t index;     // arrays: the element being read
        std::set<std::string> keys;
    };

    [[noreturn]] void fail(const std::string& what) const {
        throw JsonInputError(path_ + ": " + what);
    }

    void nextElement() {
        if (!open_.empty() && open_.back().array) ++open_.back().index;
    }

    // The field being read inside the first `levels` open arrays and objects, "" at the top.
    std::string where(size_t levels) const {
        std::string out;
        for (size_t i = 0; i < levels && out.size() <= kMaxEchoChars; ++i) {
            const Level& level = open_[i];
            if (level.array)
                out += "[" + std::to_string(level.index) + "]";
            else
                out += (out.empty() ? "" : ".") + echoText(level.key);
        }
        return cut(out, kMaxEchoChars);
    }

    const std::string& path_;
    JsonRules rules_;
    std::vector<Level> open_;
};

json parseOrDiscard(const std::string& path, const char* begin, const char* end, JsonRules rules) {
    try {
        return json::parse(begin, end, ParseWatcher(path, rules));
    } catch (const json::exception&) {
        if (rules.malformedIsDiscarded) return json(json::value_t::discarded);
        throw;
    }
}

}  // namespace

std::string echoText(const std::string& text, size_t limit) {
    std::string out;
    for (size_t i = 0; i < text.size() && out.size() <= limit; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c != 0x7F) {
            out += char(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            static const char* hex = "0123456789abcdef";
            out += std::string("\\u00") + hex[c >> 4] + hex[c & 15];
        }
    }
    return cut(out, limit);
}

std::string echo(const json& value) {
    std::string out;
    appendEcho(value, out, kMaxEchoChars);
    return cut(out, kMaxEchoChars);
}

json parseJson(const std::string& path, const char* begin, const char* end, JsonRules rules) {
    try {
        return parseOrDiscard(path, begin, end, rules);
    } catch (const json::parse_error& e) {
        throw JsonInputError(path + ": malformed JSON at byte " + std::to_string(e.byte) + ": " +
                             shortenedReason(e.what()));
    } catch (const json::exception& e) {  // e.g. 1e400: number overflow
        throw JsonInputError(path + ": malformed JSON: " + shortenedReason(e.what()));
    }
}

json readJsonFile(const std::string& path, const std::string& what, uint64_t cap) {
    std::string text;
    try {
        text = readInputFile(path, what, cap);
    } catch (const InputFileError& e) {
        throw JsonInputError(e.what());
    }
    return parseJson(path, text.data(), text.data() + text.size());
}

}  // namespace host
