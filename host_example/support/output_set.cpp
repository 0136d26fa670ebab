#include "output_set.h"

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "file_bytes.h"
#include "referenced_files.h"

namespace host {
namespace {

namespace fs = std::filesystem;

fs::path resolved(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path).lexically_normal() : p;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
    return resolved(a) == resolved(b);
}

void OutputSet::addInput(const std::string& what, const std::string& path) {
    inputs_.push_back({what, path});
}

void OutputSet::check(const std::string& option, const std::string& path) const {
    const std::string named = option + " " + path;
    if (path.empty()) throw std::runtime_error(option + " needs a file name");
    for (const Output& o : outputs_)
        if (sameFile(o.path, path))
            throw std::runtime_error(named + ": is the same file as " + o.option + " " + o.path +
                                     "; give each output its own file");
    for (const Input& in : inputs_)
        if (sameFile(in.path, path))
            throw std::runtime_error(named + ": is " + in.what + " (" + in.path +
                                     "); an output must not overwrite an input");
    const std::string folder = fs::path(path).parent_path().string();
    for (const ReferencedFile& f : filesReferencedFrom(folder))
        if (sameFile(f.path, path))
            throw std::runtime_error(named + ": is a file that " + f.referrer +
                                     " reads; an output must not overwrite a scene's file");
    // rename() would replace a device node or fail on a directory only after all the work.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw std::runtime_error(
            named + ": " +
            (S_ISDIR(st.st_mode) ? "is a directory" : "exists and is not a regular file") +
            "; give a file name");
}

void OutputSet::add(const std::string& option, const std::string& path) {
    check(option, path);
    // The check that the folder is writable: a temporary made there and removed at once. The one
    // written later is made again, so that no empty temporary waits through a long render.
    { TempFile probe(path, option); }
    outputs_.push_back({option, path, nullptr});
}

OutputSet::Output& OutputSet::find(const std::string& path) {
    for (Output& o : outputs_)
        if (o.path == path) return o;
    throw std::logic_error(path + ": written without being added to the outputs");
}

void OutputSet::write(const std::string& path, const std::vector<uint8_t>& bytes,
                      const std::string& what) {
    Output& o = find(path);
    o.temp = std::make_unique<TempFile>(path, o.option);
    const std::string why = writeWholeFile(o.temp->path(), bytes.data(), bytes.size());
    if (!why.empty()) {
        o.temp.reset();  // nothing half-written is left behind
        throw std::runtime_error(o.option + " " + path + ": cannot write the " + what + ": " + why);
    }
    o.written = true;
}

void OutputSet::writeText(const std::string& path, const std::string& text) {
    write(path, std::vector<uint8_t>(text.begin(), text.end()), "file");
}

void OutputSet::commit() {
    for (const Output& o : outputs_)
        if (!o.written || !o.temp) throw std::logic_error(o.path + ": never written");
    for (Output& o : outputs_) o.temp->moveIntoPlace();
    outputs_.clear();
}

}  // namespace host
