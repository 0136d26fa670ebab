#include "scene/json_input.h"

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

// Builds the value from the parser's events, as nlohmann's own DOM builder does, and follows them
// to know where it is ("camera.position[2]"), to cap the depth and to see repeated keys as they are
// read. nlohmann's callback parser would do the same, but after every object it closes it scans
// the enclosing container for the value it may have to discard: quadratic in the number of objects
// in one array or object (a million empty objects took minutes). Every event here costs O(1) or a
// lookup in the open object.
class DomBuilder {
  public:
    DomBuilder(const std::string& path, JsonRules rules) : path_(path), rules_(rules) {}

    json take() { return std::move(root_); }

    bool null() { return value(nullptr); }
    bool boolean(bool v) { return value(v); }
    bool number_integer(json::number_integer_t v) { return value(v); }
    bool number_unsigned(json::number_unsigned_t v) { return value(v); }
    bool number_float(json::number_float_t v, const json::string_t&) { return value(v); }
    bool string(json::string_t& v) { return value(std::move(v)); }
    bool binary(json::binary_t& v) { return value(std::move(v)); }

    bool start_object(size_t) { return open(json::value_t::object); }
    bool start_array(size_t) { return open(json::value_t::array); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(json::string_t& name) {
        Level& object = open_.back();
        auto& members = object.value->get_ref<json::object_t&>();
        if (rules_.refuseDuplicateKeys && members.find(name) != members.end()) {
            const std::string in = where(open_.size() - 1);
            fail((in.empty() ? "" : in + ": ") + "key '" + echoText(name) +
                 "' appears twice in one object");
        }
        // nlohmann keeps the last of two equal keys; so does this.
        slot_ = &members[name];
        object.key = std::move(name);
        return true;
    }

    // Thrown as the type nlohmann gives (parse_error, or out_of_range for a number too large),
    // which parseJson reports.
    template <class Exception>
    bool parse_error(size_t, const std::string&, const Exception& ex) {
        throw ex;
    }

  private:
    struct Level {
        json* value;      // the open array or object
        std::string key;  // objects: the key being read
    };

    [[noreturn]] void fail(const std::string& what) const {
        throw JsonInputError(path_ + ": " + what);
    }

    // Where the next value goes: the top, the end of the open array, or the open object's key.
    json* place(json v) {
        if (open_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        json& parent = *open_.back().value;
        if (parent.is_array()) {
            auto& elements = parent.get_ref<json::array_t&>();
            elements.push_back(std::move(v));
            return &elements.back();
        }
        *slot_ = std::move(v);
        return slot_;
    }

    template <class T>
    bool value(T&& v) {
        place(json(std::forward<T>(v)));
        return true;
    }

    bool open(json::value_t type) {
        if (open_.size() >= kMaxJsonDepth) {
            fail(where(open_.size()) + ": arrays and objects nest more than " +
                 std::to_string(kMaxJsonDepth) + " deep here (the most this reader takes)");
        }
        open_.push_back({place(json(type)), {}});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    // The field being read inside the first `levels` open arrays and objects, "" at the top. An
    // open array's element being read is its last one, or the next one when `levels` reaches the
    // innermost (a value not placed yet).
    std::string where(size_t levels) const {
        std::string out;
        for (size_t i = 0; i < levels && out.size() <= kMaxEchoChars; ++i) {
            const Level& level = open_[i];
            if (level.value->is_array()) {
                const size_t placed = level.value->size();
                const bool inner = i + 1 < open_.size();
                out += "[" + std::to_string(inner ? placed - 1 : placed) + "]";
            } else {
                out += (out.empty() ? "" : ".") + echoText(level.key);
            }
        }
        return cut(out, kMaxEchoChars);
    }

    const std::string& path_;
    JsonRules rules_;
    json root_;
    std::vector<Level> open_;
    json* slot_ = nullptr;  // the value of the open object's last key
};

json parseOrDiscard(const std::string& path, const char* begin, const char* end, JsonRules rules) {
    try {
        DomBuilder builder(path, rules);
        json::sax_parse(begin, end, &builder);
        return builder.take();
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
