// Occluders from the shipped scenes' glTF: one oriented box per connected part of a primitive, on
// its node's axes, every triangle inside one, and inner boxes only for parts that are solid boxes.
#include <gtest/gtest.h>

#include "scene/bounding_boxes.h"

namespace {

std::string scenePath(const char* name) {
    return std::string(LS_SOURCE_DIR) + "/scenes/" + name;
}

}  // namespace

TEST(BoundingBoxes, EncloseThePartsOfTheShippedScenes) {
    for (const char* name :
         {"window_room.json", "atrium.json", "engine_spot.json", "point_fog.json"}) {
        const host::SceneDesc scene = host::loadSceneFile(scenePath(name));
        const host::MeshData mesh = host::loadSceneMeshes(scene);
        const auto boxes = host::boundingBoxes(mesh);
        ASSERT_GE(boxes.size(), mesh.primitives.size()) << name;
        size_t inner = 0;
        for (const auto& b : boxes) {
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(glm::length(b.outer.axes[k]), 1.0f, 1e-5f);
                EXPECT_NEAR(glm::dot(b.outer.axes[k], b.outer.axes[(k + 1) % 3]), 0.0f, 1e-5f);
                EXPECT_GT(b.outer.halfExtents[k], 0.0f);
            }
            if (b.inner) {
                ++inner;
                for (int k = 0; k < 3; ++k)
                    EXPECT_LT(b.inner->halfExtents[k], b.outer.halfExtents[k]);
            }
        }
        // Every triangle lies whole in one box.
        auto inside = [](const host::OrientedBox& b, const glm::vec3& p) {
            const glm::vec3 local = glm::transpose(b.axes) * (p - b.center);
            for (int k = 0; k < 3; ++k)
                if (std::fabs(local[k]) > b.halfExtents[k] * 1.0001f + 1e-5f) return false;
            return true;
        };
        size_t outside = 0;
        for (const host::Primitive& p : mesh.primitives)
            for (uint32_t t = p.firstIndex; t < p.firstIndex + p.indexCount; t += 3) {
                bool held = false;
                for (const auto& b : boxes)
                    held = held || (inside(b.outer, mesh.vertices[mesh.indices[t]].position) &&
                                    inside(b.outer, mesh.vertices[mesh.indices[t + 1]].position) &&
                                    inside(b.outer, mesh.vertices[mesh.indices[t + 2]].position));
                outside += held ? 0 : 1;
            }
        EXPECT_EQ(outside, 0u) << name;
        std::printf("%s: %zu primitives, %zu connected parts, %zu solid boxes with an inner box\n",
                    name, mesh.primitives.size(), boxes.size(), inner);
    }
}

// Two flat-shaded cubes in one primitive (24 vertices each, positions repeated per face): two
// parts, each a solid box, though no index is shared between a cube's faces.
TEST(BoundingBoxes, APrimitiveSplitsIntoItsConnectedParts) {
    host::MeshData mesh;
    host::Primitive p;
    for (const glm::vec3 centre : {glm::vec3(0, 0.5f, 0), glm::vec3(4, 1, 0)}) {
        for (int axis = 0; axis < 3; ++axis)
            for (float sign : {-1.0f, 1.0f}) {
                const uint32_t base = static_cast<uint32_t>(mesh.vertices.size());
                for (int corner = 0; corner < 4; ++corner) {
                    glm::vec3 local(0.0f);
                    local[axis] = 0.5f * sign;
                    local[(axis + 1) % 3] = corner & 1 ? 0.5f : -0.5f;
                    local[(axis + 2) % 3] = corner & 2 ? 0.5f : -0.5f;
                    host::Vertex v;
                    v.position = centre + local;
                    mesh.vertices.push_back(v);
                }
                for (uint32_t i : {0u, 1u, 3u, 0u, 3u, 2u}) mesh.indices.push_back(base + i);
            }
    }
    p.vertexCount = static_cast<uint32_t>(mesh.vertices.size());
    p.indexCount = static_cast<uint32_t>(mesh.indices.size());
    mesh.primitives.push_back(p);
    const auto boxes = host::boundingBoxes(mesh);
    ASSERT_EQ(boxes.size(), 2u);
    for (const auto& b : boxes) {
        EXPECT_NEAR(b.outer.halfExtents.x, 0.5f, 1e-5f);
        EXPECT_TRUE(b.inner.has_value());
    }
    EXPECT_NEAR(boxes[0].outer.center.x + boxes[1].outer.center.x, 4.0f, 1e-5f);
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

// More separate parts than the beam tree takes (issue #22: 100,000 disjoint triangles could not be
// rendered by any method): the grid's boxes are at most the limit, enclose every triangle and do
// not overlap one another.
TEST(BoundingBoxes, AGridOfBoxesHoldsManyPartsWithinTheLimit) {
    host::MeshData mesh;
    host::Primitive p;
    uint32_t seed = 12345;
    auto next = [&] {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<float>(seed >> 8) / 16777216.0f;
    };
    for (int t = 0; t < 20000; ++t) {
        const glm::vec3 at(next() * 40.0f - 20.0f, next() * 6.0f, next() * 40.0f - 20.0f);
        for (int k = 0; k < 3; ++k) {
            host::Vertex v;
            v.position = at + 0.05f * glm::vec3(next(), next(), next());
            mesh.indices.push_back(static_cast<uint32_t>(mesh.vertices.size()));
            mesh.vertices.push_back(v);
        }
    }
    p.vertexCount = static_cast<uint32_t>(mesh.vertices.size());
    p.indexCount = static_cast<uint32_t>(mesh.indices.size());
    mesh.primitives.push_back(p);
    ASSERT_EQ(host::boundingBoxes(mesh).size(), 20000u);
    const auto boxes = host::gridBoxes(mesh, 4096);
    ASSERT_GT(boxes.size(), 100u);
    ASSERT_LE(boxes.size(), 4096u);
    auto lo = [](const host::BoundingBoxes& b) { return b.outer.center - b.outer.halfExtents; };
    auto hi = [](const host::BoundingBoxes& b) { return b.outer.center + b.outer.halfExtents; };
    for (const auto& b : boxes) {
        EXPECT_FALSE(b.inner.has_value());
        EXPECT_EQ(b.outer.axes, glm::mat3(1.0f));
    }
    for (const host::Vertex& v : mesh.vertices) {
        bool inside = false;
        for (size_t i = 0; i < boxes.size() && !inside; ++i)
            inside = glm::all(glm::greaterThanEqual(v.position, lo(boxes[i]) - 1e-4f)) &&
                     glm::all(glm::lessThanEqual(v.position, hi(boxes[i]) + 1e-4f));
        ASSERT_TRUE(inside) << v.position.x << " " << v.position.y << " " << v.position.z;
    }
    // Overlaps only where a box was given its minimum thickness (a millimetre).
    for (size_t i = 0; i < boxes.size(); ++i)
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            const glm::vec3 overlap =
                glm::min(hi(boxes[i]), hi(boxes[j])) - glm::max(lo(boxes[i]), lo(boxes[j]));
            ASSERT_FALSE(glm::all(glm::greaterThan(overlap, glm::vec3(2e-3f))))
                << i << " and " << j;
        }
}
