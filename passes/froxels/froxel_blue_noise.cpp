#include "froxel_blue_noise.h"

#include <algorithm>
#include <cmath>

#include "blue_noise_comp.h"
#include "shaders/froxels/froxel_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {
namespace {

// Ulichney's filter: a Gaussian of sigma 1.5 texels, on the torus so that the tile repeats.
constexpr float kSigma = 1.5f;

struct Pattern {
    uint32_t size = 0, mask = 0;
    std::vector<float> kernel;  // by toroidal offset (dy * size + dx)
    std::vector<uint8_t> on;
    std::vector<float> energy;  // the kernel summed over the pattern's texels, at every texel

    explicit Pattern(uint32_t n)
        : size(n),
          mask(n - 1),
          kernel(size_t(n) * n),
          on(size_t(n) * n, 0),
          energy(size_t(n) * n, 0.0f) {
        for (uint32_t dy = 0; dy < n; ++dy)
            for (uint32_t dx = 0; dx < n; ++dx) {
                const float x = float(std::min(dx, n - dx)), y = float(std::min(dy, n - dy));
                kernel[size_t(dy) * n + dx] = std::exp(-(x * x + y * y) / (2.0f * kSigma * kSigma));
            }
    }

    void set(uint32_t p, bool value) {
        on[p] = value ? 1 : 0;
        const float sign = value ? 1.0f : -1.0f;
        const uint32_t px = p & mask, py = p / size;
        for (uint32_t y = 0; y < size; ++y) {
            const float* row = &kernel[size_t((y - py) & mask) * size];
            float* e = &energy[size_t(y) * size];
            for (uint32_t x = 0; x < size; ++x) e[x] += sign * row[(x - px) & mask];
        }
    }

    // The texel of the pattern with the most energy (`value` 1: the tightest cluster) or of the
    // gaps with the least (`value` 0: the largest void); the first such texel, so that the tile
    // depends on nothing but the seed.
    uint32_t extreme(bool value) const {
        uint32_t best = 0;
        bool found = false;
        for (uint32_t p = 0; p < on.size(); ++p) {
            if (bool(on[p]) != value) continue;
            if (!found || (value ? energy[p] > energy[best] : energy[p] < energy[best])) best = p;
            found = true;
        }
        return best;
    }
};

uint64_t splitmix(uint64_t& state) {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace

std::vector<float> voidAndClusterTile(uint32_t size, uint64_t seed) {
    const uint32_t n = size * size;
    Pattern pattern(size);
    // The starting pattern: a tenth of the texels, at random.
    const uint32_t ones = std::max(n / 10, 1u);
    for (uint32_t placed = 0; placed < ones;) {
        const uint32_t p = uint32_t(splitmix(seed) % n);
        if (pattern.on[p]) continue;
        pattern.set(p, true);
        ++placed;
    }
    // Spread it: the tightest cluster's texel moves to the largest void until it would move back
    // (bounded, though it ends long before).
    for (uint32_t moves = 0; moves < 4 * n; ++moves) {
        const uint32_t cluster = pattern.extreme(true);
        pattern.set(cluster, false);
        const uint32_t gap = pattern.extreme(false);
        pattern.set(gap, true);
        if (gap == cluster) break;
    }
    std::vector<uint32_t> rank(n, 0);
    // Ranks below `ones`: the pattern's texels, the tightest cluster taken out first.
    Pattern taken = pattern;
    for (uint32_t r = ones; r > 0; --r) {
        const uint32_t cluster = taken.extreme(true);
        taken.set(cluster, false);
        rank[cluster] = r - 1;
    }
    // The rest: each in the largest void left. (Ulichney's third phase takes the gaps' tightest
    // cluster once half the texels are set; on the torus the gaps' energy is a constant minus
    // the pattern's, so that is this same texel.)
    for (uint32_t r = ones; r < n; ++r) {
        const uint32_t gap = pattern.extreme(false);
        pattern.set(gap, true);
        rank[gap] = r;
    }
    std::vector<float> tile(n);
    for (uint32_t p = 0; p < n; ++p) tile[p] = (float(rank[p]) + 0.5f) / float(n);
    return tile;
}

const std::vector<float>& froxelBlueNoise() {
    static const std::vector<float> tile = voidAndClusterTile(kFroxelNoiseSize, 1);
    return tile;
}

rg::PersistentImageDesc froxelBlueNoiseDesc() {
    rg::PersistentImageDesc d;
    d.format = VK_FORMAT_R32_SFLOAT;
    d.extent = {kFroxelNoiseSize, kFroxelNoiseSize};
    // Read as storage; sampled too, so that it may rest in SHADER_READ_ONLY_OPTIMAL between
    // frames, as the froxel history does.
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    d.stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    d.handAccess = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    return d;
}

rg::ImageRef addFroxelBlueNoise(rg::RenderGraph& graph, const FroxelBlueNoiseInputs& in) {
    const rg::ImageRef kept =
        graph.persistentImage("froxel blue noise", froxelBlueNoiseDesc(), in.key);
    constexpr VkDeviceSize kBytes =
        VkDeviceSize{kFroxelNoiseSize} * kFroxelNoiseSize * sizeof(float);
    static_assert(kBytes <= 65536, "one vkCmdUpdateBuffer");
    // The texels reach the GPU through a buffer the frame updates, as the frame constants do; a
    // compute pass then writes them into the image, as every other persistent image is written.
    rg::BufferRef texels = graph.createBuffer("froxel blue noise texels", {kBytes});
    auto upload = graph.addPass("upload froxel blue noise", rg::PassType::Transfer);
    texels = upload.transferDst(texels);
    upload.execute([texels, kept](rg::PassContext& ctx) {
        if (ctx.persistent(kept).written) return;  // made in an earlier frame
        ctx.vk().CmdUpdateBuffer(ctx.cmd(), ctx.buffer(texels), 0, kBytes,
                                 froxelBlueNoise().data());
    });
    auto pass = graph.addPass("froxel blue noise", rg::PassType::Compute);
    rg::BindingTable table(pass);
    table.storageBufferRead(LS_BINDING_FROXEL_NOISE_TEXELS, texels);
    const rg::ImageRef noise = table.storageWrite(LS_BINDING_FROXEL_NOISE_OUT, kept);
    pass.execute([shared = in.shared, table, noise](rg::PassContext& ctx) {
        if (ctx.persistent(noise).written) return;
        const auto& p = shared->pipelines.compute(
            "froxel blue noise", rg::spirv(ls_spirv::blue_noise_comp), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(kFroxelNoiseSize, 8),
                             groupCount(kFroxelNoiseSize, 8), 1);
        ctx.wrote(noise, 1);
    });
    return noise;
}

}  // namespace ls
