#pragma once
// Seed 004's CPU half for one frame: the beam tree of the occluders' bounding volumes, built anew
// each frame, and the triangles it gives the GPU. The hybrid (5.4) gets the fully lit pyramids'
// surfaces and the uncertain parts of seed 002's sampling planes; sampling with aggressive clipping
// (5.3) gets the planes' lit parts and their uncertain parts. Unlit parts are never drawn. Plain
// C++; the nodes upload the result.
#include <memory>
#include <vector>

#include "beam_tree/occluders.h"
#include "planes/plane_geometry.h"
#include "planes/plane_settings.h"
#include "shared/scattering_params.h"

namespace ls {

struct BeamTreeFrame {
    // Triangles: the lit space's (pyramids or plane parts), then the uncertain planes' parts.
    std::vector<glm::vec4> points;
    uint32_t litPoints = 0, uncertainPoints = 0;
    bool litAsPlanes = false;  // the lit triangles are plane parts (5.3), not pyramids (5.4)
    PlanePush planePush;       // the sampling planes' placement (spacing) for their shading
    // Where each plane's triangles start within the lit (when litAsPlanes) and the uncertain
    // triangles, one entry per plane and one past the last; and the planes [nearFirst, nearEnd)
    // near the light's depth, nearSpacing apart (thinner than the others), whose slabs take the
    // closed form (planes.frag).
    std::vector<uint32_t> litStarts, uncertainStarts;
    uint32_t nearFirst = 0, nearEnd = 0;
    float nearSpacing = 0.0f;
    double buildMilliseconds = 0;  // CPU: tree, pyramids and plane partition
    size_t treeNodes = 0, visiblePolygons = 0;
};

// For a point or spot light. A spot's frustum is the four walls around its cone cut at its range; a
// point light's is a cube around it as far as the view reaches. `planes`: the sampling planes.
enum class LitSpace { ClosedForm, Planes };
BeamTreeFrame buildBeamTreeFrame(const CameraParams& camera, const LightParams& light,
                                 const MediumParams& medium,
                                 const std::vector<beam::Occluder>& occluders,
                                 const PlaneSettings& planes, LitSpace lit = LitSpace::ClosedForm);

}  // namespace ls
