#pragma once
// The files that the scenes and glTF models of a folder read, so that an output written into that
// folder never replaces another scene's model, buffer or texture (issue #22: `render a.json --out
// scenes/atrium_floor.png` overwrote the atrium's floor). The scan is lenient: a file that is not a
// scene or a glTF, or cannot be read, references nothing.
#include <string>
#include <vector>

namespace host {

struct ReferencedFile {
    std::string path;      // as resolved from the referencing file's folder
    std::string referrer;  // the scene or glTF file that names it
};

// Every file a SCENE.json (its "gltf" and "models[].gltf"), a .gltf or a .glb (their buffers' and
// images' URIs) in `folder` names, and the files of the glTF models those scenes name, wherever
// those are. Data URIs name no file.
std::vector<ReferencedFile> filesReferencedFrom(const std::string& folder);

}  // namespace host
