#pragma once
// What the fuzz targets share: the fuzzer's bytes as a file the readers can open, and the rule
// every refusal must keep (one line that names the file, of bounded length).
#include <cstddef>
#include <cstdint>
#include <string>

namespace fuzz {

// A folder of this process's own under $TMPDIR that holds links to every file of scenes/ and
// scenes/hard/, so that the relative paths of the shipped scenes and glTF files (atrium.gltf,
// atrium.bin, ...) resolve from there.
const std::string& inputFolder();

// Writes the input to NAME in inputFolder() and returns its path.
const std::string& writeInput(const uint8_t* data, size_t size, const std::string& name);

// Aborts (a finding) unless `message` starts with "PATH: ", holds no newline and is at most
// `limit` characters: the readers' promise of one clear line.
void checkRefusal(const std::string& message, const std::string& path, size_t limit = 4096);

}  // namespace fuzz
