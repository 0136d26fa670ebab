#pragma once
// The files a command reads for one scene, named for the output checks (output_set.h): the scene
// file, its models with their buffers and images, and its lights' cookies. Every command that
// writes (render, view, bench) counts all of them, so that none of its outputs overwrites one:
// bench once left the cookies out, and a cookie named like its CSV became the CSV.
#include <string>

#include "output_set.h"
#include "scene/scene.h"

namespace host {

// `whose` qualifies the names: "the scene" for render and view, "a scene of the benchmark".
// `scenePath` as the user gave it (messages quote it).
void addSceneInputs(OutputSet& outputs, const std::string& scenePath, const SceneDesc& scene,
                    const MeshData& mesh, const std::string& whose);

}  // namespace host
