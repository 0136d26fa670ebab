// Occluders from the shipped scenes' glTF: every primitive's vertices inside its oriented box, the
// box on the node's axes, and inner boxes only for primitives that are solid boxes.
#include <gtest/gtest.h>

#include "scene/bounding_boxes.h"

namespace {

std::string scenePath(const char* name) {
    return std::string(LS_SOURCE_DIR) + "/scenes/" + name;
}

}  // namespace

TEST(BoundingBoxes, EnclosePrimitivesOfTheShippedScenes) {
    for (const char* name :
         {"window_room.json", "atrium.json", "engine_spot.json", "point_fog.json"}) {
        const host::SceneDesc scene = host::loadSceneFile(scenePath(name));
        const host::MeshData mesh = host::loadSceneMeshes(scene);
        const auto boxes = host::boundingBoxes(mesh);
        ASSERT_EQ(boxes.size(), mesh.primitives.size()) << name;
        size_t inner = 0;
        for (size_t i = 0; i < boxes.size(); ++i) {
            const host::Primitive& p = mesh.primitives[i];
            const host::OrientedBox& b = boxes[i].outer;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(glm::length(b.axes[k]), 1.0f, 1e-5f);
                EXPECT_NEAR(glm::dot(b.axes[k], b.axes[(k + 1) % 3]), 0.0f, 1e-5f);
                EXPECT_GT(b.halfExtents[k], 0.0f);
            }
            for (uint32_t v = 0; v < p.vertexCount; ++v) {
                const glm::vec3 local =
                    glm::transpose(b.axes) * (mesh.vertices[p.firstVertex + v].position - b.center);
                for (int k = 0; k < 3; ++k)
                    EXPECT_LE(std::fabs(local[k]), b.halfExtents[k] * 1.0001f + 1e-5f) << name;
            }
            if (boxes[i].inner) {
                ++inner;
                for (int k = 0; k < 3; ++k)
                    EXPECT_LT(boxes[i].inner->halfExtents[k], b.halfExtents[k]);
            }
        }
        std::printf("%s: %zu primitives, %zu solid boxes with an inner box\n", name, boxes.size(),
                    inner);
    }
}

TEST(BoundingBoxes, ACubeIsASolidBoxAndATriangleIsNot) {
    host::MeshData mesh;
    // A unit cube's 8 corners (as 24 vertices would be), rotated 30 degrees about y.
    const float c = std::cos(0.5236f), s = std::sin(0.5236f);
    const glm::mat3 axes(glm::vec3(c, 0, -s), glm::vec3(0, 1, 0), glm::vec3(s, 0, c));
    for (int k = 0; k < 8; ++k) {
        host::Vertex v;
        v.position =
            axes * glm::vec3(k & 1 ? 0.5f : -0.5f, k & 2 ? 0.5f : -0.5f, k & 4 ? 0.5f : -0.5f) +
            glm::vec3(3, 1, 0);
        mesh.vertices.push_back(v);
    }
    host::Primitive cube;
    cube.firstVertex = 0;
    cube.vertexCount = 8;
    cube.axes = axes;
    mesh.primitives.push_back(cube);
    host::Primitive triangle;
    triangle.firstVertex = 0;
    triangle.vertexCount = 3;  // three corners: not every corner is there, but all are corners
    triangle.axes = axes;
    mesh.primitives.push_back(triangle);
    host::Vertex mid;
    mid.position = glm::vec3(3, 1, 0);  // the cube's centre: not a corner
    mesh.vertices.push_back(mid);
    host::Primitive withCentre;
    withCentre.firstVertex = 0;
    withCentre.vertexCount = 9;
    withCentre.axes = axes;
    mesh.primitives.push_back(withCentre);
    const auto boxes = host::boundingBoxes(mesh);
    ASSERT_EQ(boxes.size(), 3u);
    EXPECT_NEAR(glm::length(boxes[0].outer.center - glm::vec3(3, 1, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(boxes[0].outer.halfExtents.x, 0.5f, 1e-5f);
    ASSERT_TRUE(boxes[0].inner.has_value());
    EXPECT_NEAR(boxes[0].inner->halfExtents.y, 0.499f, 1e-5f);
    EXPECT_FALSE(boxes[1].inner.has_value());  // flat
    EXPECT_FALSE(boxes[2].inner.has_value());
}
