// The null method's Lin (tests/new_method): every pixel of the EXR that the light reaches holds the
// value its settings gave, and the light reaches most of them. Pixels outside the light's screen
// rectangle are 0 (the Lin nodes clear what they do not draw).
//   test_constant_lin FILE.exr VALUE
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "image_io.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: test_constant_lin FILE.exr VALUE\n");
        return 2;
    }
    try {
        const host::FloatImage image = host::readExr(argv[1]);
        const double value = std::strtod(argv[2], nullptr);
        const size_t pixels = size_t{image.width} * image.height;
        size_t lit = 0;
        for (size_t i = 0; i < pixels; ++i) {
            for (int c = 0; c < 3; ++c) {
                const double v = image.rgba[4 * i + c];
                // Lin passes through a half-float target: 11 bits of mantissa.
                const bool isValue = std::abs(v - value) <= value * 1e-3;
                if (!isValue && v != 0.0) {
                    std::fprintf(stderr, "%s: pixel (%zu, %zu) channel %d holds %g, not %g or 0\n",
                                 argv[1], i % image.width, i / image.width, c, v, value);
                    return 1;
                }
                if (isValue && c == 0) ++lit;
            }
        }
        std::printf("%s: %zu of %zu pixels hold %g, the others 0\n", argv[1], lit, pixels, value);
        if (2 * lit < pixels) {
            std::fprintf(stderr, "%s: the light reaches under half the pixels\n", argv[1]);
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
