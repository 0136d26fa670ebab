#include "mesh_builder.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace make_scenes {

int MeshBuilder::addTexture(TextureImage image) {
    textures_.push_back(std::move(image));
    return static_cast<int>(textures_.size()) - 1;
}

int MeshBuilder::addMaterial(MaterialDef material, float uvPerMetre) {
    materials_.push_back(std::move(material));
    uvScale_.push_back(uvPerMetre);
    prims_.emplace_back();
    prims_.back().material = static_cast<int>(materials_.size()) - 1;
    return prims_.back().material;
}

void MeshBuilder::use(int material) {
    if (material < 0 || material >= static_cast<int>(materials_.size()))
        throw std::out_of_range("MeshBuilder::use: no such material");
    current_ = material;
}

void MeshBuilder::place(const glm::mat4& transform) {
    transform_ = transform;
    normalMatrix_ = glm::transpose(glm::inverse(glm::mat3(transform)));
}

glm::vec2 MeshBuilder::planarUv(const glm::vec3& p, const glm::vec3& n) const {
    // Project on the plane most facing the normal, so textures keep their size in metres.
    const glm::vec3 a = glm::abs(n);
    glm::vec2 uv;
    if (a.y >= a.x && a.y >= a.z)
        uv = {p.x, p.z};
    else if (a.x >= a.z)
        uv = {p.z, -p.y};
    else
        uv = {p.x, -p.y};
    return uv * uvScale_[static_cast<size_t>(current_)];
}

uint32_t MeshBuilder::vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
    if (current_ < 0) throw std::logic_error("MeshBuilder: no material in use");
    PrimitiveData& prim = prims_[static_cast<size_t>(current_)];
    prim.positions.push_back(glm::vec3(transform_ * glm::vec4(p, 1.0f)));
    prim.normals.push_back(glm::normalize(normalMatrix_ * n));
    prim.uvs.push_back(uv);
    return static_cast<uint32_t>(prim.positions.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c, const glm::vec3& facing) {
    PrimitiveData& prim = prims_[static_cast<size_t>(current_)];
    const glm::vec3 geo =
        glm::cross(prim.positions[b] - prim.positions[a], prim.positions[c] - prim.positions[a]);
    if (glm::dot(geo, normalMatrix_ * facing) < 0.0f) std::swap(b, c);
    prim.indices.insert(prim.indices.end(), {a, b, c});
}

void MeshBuilder::quad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                       const glm::vec3& p3, const glm::vec3& normal) {
    const glm::vec3 n = glm::normalize(normal);
    const uint32_t i0 = vertex(p0, n, planarUv(p0, n));
    const uint32_t i1 = vertex(p1, n, planarUv(p1, n));
    const uint32_t i2 = vertex(p2, n, planarUv(p2, n));
    const uint32_t i3 = vertex(p3, n, planarUv(p3, n));
    triangle(i0, i1, i2, n);
    triangle(i0, i2, i3, n);
}

void MeshBuilder::box(const glm::vec3& center, const glm::vec3& half, const glm::mat3& rotation) {
    for (int axis = 0; axis < 3; ++axis) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (float sign : {-1.0f, 1.0f}) {
            const glm::vec3 n = rotation[axis] * sign;
            const glm::vec3 c = center + n * half[axis];
            const glm::vec3 t1 = rotation[a1] * half[a1];
            const glm::vec3 t2 = rotation[a2] * half[a2];
            quad(c - t1 - t2, c + t1 - t2, c + t1 + t2, c - t1 + t2, n);
        }
    }
}

void MeshBuilder::boxMinMax(const glm::vec3& lo, const glm::vec3& hi) {
    box((lo + hi) * 0.5f, (hi - lo) * 0.5f);
}

void MeshBuilder::cylinder(const glm::vec3& baseCenter, float radius, float height, int sides) {
    const float uvs = uvScale_[static_cast<size_t>(current_)];
    const glm::vec3 top = baseCenter + glm::vec3(0.0f, height, 0.0f);
    std::vector<uint32_t> lower, upper;
    for (int i = 0; i <= sides; ++i) {
        const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i % sides) /
                          static_cast<float>(sides);
        const glm::vec3 n(std::cos(phi), 0.0f, std::sin(phi));
        const float u = static_cast<float>(i) / static_cast<float>(sides) * 2.0f *
                        std::numbers::pi_v<float> * radius * uvs;
        lower.push_back(vertex(baseCenter + n * radius, n, {u, 0.0f}));
        upper.push_back(vertex(top + n * radius, n, {u, -height * uvs}));
    }
    for (int i = 0; i < sides; ++i) {
        const float phi = 2.0f * std::numbers::pi_v<float> * (static_cast<float>(i) + 0.5f) /
                          static_cast<float>(sides);
        const glm::vec3 out(std::cos(phi), 0.0f, std::sin(phi));
        const auto k = static_cast<size_t>(i);
        triangle(lower[k], lower[k + 1], upper[k + 1], out);
        triangle(lower[k], upper[k + 1], upper[k], out);
    }
    for (float sign : {-1.0f, 1.0f}) {
        const glm::vec3 n(0.0f, sign, 0.0f);
        const glm::vec3 c = sign < 0.0f ? baseCenter : top;
        const uint32_t centre = vertex(c, n, planarUv(c, n));
        std::vector<uint32_t> ring;
        for (int i = 0; i < sides; ++i) {
            const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) /
                              static_cast<float>(sides);
            const glm::vec3 p = c + glm::vec3(std::cos(phi), 0.0f, std::sin(phi)) * radius;
            ring.push_back(vertex(p, n, planarUv(p, n)));
        }
        for (size_t i = 0; i < ring.size(); ++i)
            triangle(centre, ring[i], ring[(i + 1) % ring.size()], n);
    }
}

void MeshBuilder::cone(const glm::vec3& baseCenter, float radius, float height, int sides) {
    const float pi = std::numbers::pi_v<float>;
    const glm::vec3 apex = baseCenter + glm::vec3(0.0f, height, 0.0f);
    const float slant = std::sqrt(radius * radius + height * height);
    for (int i = 0; i < sides; ++i) {
        const float p0 = 2.0f * pi * static_cast<float>(i) / static_cast<float>(sides);
        const float p1 = 2.0f * pi * static_cast<float>(i + 1) / static_cast<float>(sides);
        const float pm = 0.5f * (p0 + p1);
        auto normalAt = [&](float phi) {
            return glm::vec3(height * std::cos(phi), radius, height * std::sin(phi)) / slant;
        };
        const glm::vec3 a = baseCenter + glm::vec3(std::cos(p0), 0.0f, std::sin(p0)) * radius;
        const glm::vec3 b = baseCenter + glm::vec3(std::cos(p1), 0.0f, std::sin(p1)) * radius;
        const glm::vec3 na = normalAt(p0), nb = normalAt(p1), nm = normalAt(pm);
        const uint32_t ia = vertex(a, na, planarUv(a, na));
        const uint32_t ib = vertex(b, nb, planarUv(b, nb));
        const uint32_t ic = vertex(apex, nm, planarUv(apex, nm));
        triangle(ia, ib, ic, nm);
    }
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const uint32_t centre = vertex(baseCenter, down, planarUv(baseCenter, down));
    std::vector<uint32_t> ring;
    for (int i = 0; i < sides; ++i) {
        const float phi = 2.0f * pi * static_cast<float>(i) / static_cast<float>(sides);
        const glm::vec3 p = baseCenter + glm::vec3(std::cos(phi), 0.0f, std::sin(phi)) * radius;
        ring.push_back(vertex(p, down, planarUv(p, down)));
    }
    for (size_t i = 0; i < ring.size(); ++i)
        triangle(centre, ring[i], ring[(i + 1) % ring.size()], down);
}

void MeshBuilder::heightfield(const glm::vec2& lo, const glm::vec2& hi, int nx, int nz,
                              const std::function<float(float, float)>& height) {
    if (nx < 1 || nz < 1) throw std::invalid_argument("MeshBuilder::heightfield: no cells");
    const float dx = (hi.x - lo.x) / static_cast<float>(nx);
    const float dz = (hi.y - lo.y) / static_cast<float>(nz);
    std::vector<uint32_t> index;
    index.reserve(static_cast<size_t>(nx + 1) * static_cast<size_t>(nz + 1));
    for (int j = 0; j <= nz; ++j) {
        for (int i = 0; i <= nx; ++i) {
            const float x = lo.x + dx * static_cast<float>(i);
            const float z = lo.y + dz * static_cast<float>(j);
            const float slopeX = (height(x + dx, z) - height(x - dx, z)) / (2.0f * dx);
            const float slopeZ = (height(x, z + dz) - height(x, z - dz)) / (2.0f * dz);
            const glm::vec3 n = glm::normalize(glm::vec3(-slopeX, 1.0f, -slopeZ));
            const glm::vec3 p(x, height(x, z), z);
            index.push_back(vertex(p, n, planarUv(p, glm::vec3(0.0f, 1.0f, 0.0f))));
        }
    }
    const auto at = [&](int i, int j) {
        return index[static_cast<size_t>(j) * static_cast<size_t>(nx + 1) + static_cast<size_t>(i)];
    };
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    for (int j = 0; j < nz; ++j) {
        for (int i = 0; i < nx; ++i) {
            // Alternate the diagonal so that ridges running either way are cut alike.
            if ((i + j) % 2 == 0) {
                triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), up);
                triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), up);
            } else {
                triangle(at(i, j), at(i + 1, j), at(i, j + 1), up);
                triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), up);
            }
        }
    }
}

void MeshBuilder::curtain(const std::vector<float>& xs, const std::vector<float>& bottom,
                          const std::vector<float>& top, float z0, float z1) {
    const size_t n = xs.size();
    if (n < 2 || bottom.size() != n || top.size() != n)
        throw std::invalid_argument("MeshBuilder::curtain: mismatched profile");
    for (size_t i = 0; i + 1 < n; ++i) {
        const glm::vec3 b0(xs[i], bottom[i], 0.0f), b1(xs[i + 1], bottom[i + 1], 0.0f);
        const glm::vec3 t0(xs[i], top[i], 0.0f), t1(xs[i + 1], top[i + 1], 0.0f);
        const glm::vec3 zf(0.0f, 0.0f, z1), zb(0.0f, 0.0f, z0);
        // Front (+z) and back (-z) faces: one trapezoid per column pair.
        quad(b0 + zf, b1 + zf, t1 + zf, t0 + zf, {0.0f, 0.0f, 1.0f});
        quad(b0 + zb, b1 + zb, t1 + zb, t0 + zb, {0.0f, 0.0f, -1.0f});
        // Underside, facing away from the solid (downwards), and the top, facing up.
        const glm::vec3 db = b1 - b0, dt = t1 - t0;
        quad(b0 + zb, b1 + zb, b1 + zf, b0 + zf, {db.y, -db.x, 0.0f});
        quad(t0 + zb, t1 + zb, t1 + zf, t0 + zf, {-dt.y, dt.x, 0.0f});
    }
    for (size_t end : {size_t{0}, n - 1}) {
        if (top[end] - bottom[end] <= 0.0f) continue;
        const float sx = end == 0 ? -1.0f : 1.0f;
        const glm::vec3 b(xs[end], bottom[end], 0.0f), t(xs[end], top[end], 0.0f);
        const glm::vec3 zf(0.0f, 0.0f, z1), zb(0.0f, 0.0f, z0);
        quad(b + zb, b + zf, t + zf, t + zb, {sx, 0.0f, 0.0f});
    }
}

std::vector<const PrimitiveData*> MeshBuilder::primitives() const {
    std::vector<const PrimitiveData*> out;
    for (const PrimitiveData& p : prims_)
        if (!p.indices.empty()) out.push_back(&p);
    return out;
}

size_t MeshBuilder::triangleCount() const {
    size_t n = 0;
    for (const PrimitiveData& p : prims_) n += p.indices.size() / 3;
    return n;
}

}  // namespace make_scenes
