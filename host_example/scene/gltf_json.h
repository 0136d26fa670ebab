#pragma once
// A glTF file's JSON (a .glb's JSON chunk) as this program's reader parses it, kept from one read
// to the next: a scene with "lightsFromGltf" has its lights read when SCENE.json is, and its mesh
// loaded after, and both read the same text, which was parsed twice (a 9 MB glTF of 400,000 nodes
// took 27-41 s when the reader was quadratic). The lights' reader keeps its document with a hash of
// the text, so a file changed in between is parsed again, and the mesh loader takes it (it is not
// held through the frames); tinygltf then reads the mesh through its own API from the same bytes.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/json_input.h"

namespace host {

// parseJson(path, begin, end, rules), or the document kept from the same path and text. With
// `keep`, the document is kept for the next call (the lights' reader); without, what was kept is
// let go (the mesh loader, the last to read it).
std::shared_ptr<const nlohmann::json> gltfJson(const std::string& path, const char* begin,
                                               const char* end, JsonRules rules, bool keep);

// How many glTF texts gltfJson has parsed in this process (for the tests: operations, not time).
size_t gltfJsonParses();

}  // namespace host
