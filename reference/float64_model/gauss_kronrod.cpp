#include "gauss_kronrod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

namespace ls::ref {
namespace {

// 15-point Kronrod abscissae on [-1, 1], positive half, largest first; the odd entries (and 0) are
// the 7-point Gauss-Legendre nodes, so one set of evaluations gives both rules.
constexpr std::array<double, 8> kNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights of kNodes[1], kNodes[3], kNodes[5] and kNodes[7] (the centre).
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
constexpr int kEvaluationsPerSegment = 15;

struct Segment {
    double a = 0.0;
    double b = 0.0;
    glm::dvec3 value{0.0};
    glm::dvec3 error{0.0};
    double priority = 0.0;
};

Segment evaluateSegment(const Integrand& f, double a, double b) {
    const double centre = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    const glm::dvec3 fc = f(centre);
    glm::dvec3 kronrod = fc * kKronrodWeights[7];
    glm::dvec3 gauss = fc * kGaussWeights[3];
    for (std::size_t j = 0; j < 7; ++j) {
        const double dx = half * kNodes[j];
        const glm::dvec3 pair = f(centre - dx) + f(centre + dx);
        kronrod += kKronrodWeights[j] * pair;
        if (j % 2 == 1) gauss += kGaussWeights[j / 2] * pair;
    }
    Segment s;
    s.a = a;
    s.b = b;
    s.value = kronrod * half;
    // |K - G| estimates the error of G7; K15 is far better, so this over-states the error and
    // the tolerance is met with margin.
    s.error = glm::abs((kronrod - gauss) * half);
    return s;
}

bool meetsTolerance(const glm::dvec3& total, const glm::dvec3& error, const QuadOptions& options) {
    for (int c = 0; c < 3; ++c) {
        if (!(error[c] <= std::max(options.relTol * std::abs(total[c]), options.absTol))) {
            return false;
        }
    }
    return true;
}

bool lowerPriority(const Segment& x, const Segment& y) {
    return x.priority < y.priority;
}

}  // namespace

QuadResult integrateAdaptive(const Integrand& f, std::span<const Interval> pieces,
                             const QuadOptions& options) {
    QuadResult result;
    std::vector<Segment> heap;
    std::vector<Segment> frozen;  // too narrow to bisect in double
    for (const Interval& piece : pieces) {
        if (piece.end > piece.begin) heap.push_back(evaluateSegment(f, piece.begin, piece.end));
    }
    result.evaluations = kEvaluationsPerSegment * static_cast<int>(heap.size());
    if (heap.empty()) return result;

    auto sumAll = [&](glm::dvec3& total, glm::dvec3& error) {
        total = glm::dvec3(0.0);
        error = glm::dvec3(0.0);
        for (const auto* list : {&heap, &frozen}) {
            for (const Segment& s : *list) {
                total += s.value;
                error += s.error;
            }
        }
    };
    glm::dvec3 total;
    glm::dvec3 error;
    sumAll(total, error);

    // Errors are compared across channels after dividing by each channel's current integral, so
    // a dim channel is refined as much as a bright one. The scale is renewed whenever an exact
    // re-sum still misses the tolerance and each time the segment count doubles, in case the first
    // estimate of a channel was far off.
    glm::dvec3 invScale(1.0);
    auto prioritise = [&](Segment& s) {
        const glm::dvec3 e = s.error * invScale;
        s.priority = std::max({e.x, e.y, e.z});
    };
    auto rescale = [&] {
        for (int c = 0; c < 3; ++c) invScale[c] = total[c] != 0.0 ? 1.0 / std::abs(total[c]) : 1.0;
        for (Segment& s : heap) prioritise(s);
        std::make_heap(heap.begin(), heap.end(), lowerPriority);
    };
    rescale();

    result.converged = false;
    std::size_t nextRescale = 2 * heap.size() + 16;
    while (true) {
        const std::size_t count = heap.size() + frozen.size();
        if (meetsTolerance(total, error, options) || count >= nextRescale) {
            // The running sums drift with each update; only an exact re-sum may end the loop.
            sumAll(total, error);
            if (meetsTolerance(total, error, options)) {
                result.converged = true;
                break;
            }
            rescale();
            nextRescale = 2 * count;
        }
        if (heap.empty() || static_cast<int>(heap.size() + frozen.size()) >= options.maxSegments) {
            break;
        }
        std::pop_heap(heap.begin(), heap.end(), lowerPriority);
        const Segment worst = heap.back();
        heap.pop_back();
        const double mid = 0.5 * (worst.a + worst.b);
        if (!(worst.a < mid && mid < worst.b)) {
            frozen.push_back(worst);
            continue;
        }
        Segment left = evaluateSegment(f, worst.a, mid);
        Segment right = evaluateSegment(f, mid, worst.b);
        result.evaluations += 2 * kEvaluationsPerSegment;
        total += left.value + right.value - worst.value;
        error += left.error + right.error - worst.error;
        for (Segment* s : {&left, &right}) {
            prioritise(*s);
            heap.push_back(*s);
            std::push_heap(heap.begin(), heap.end(), lowerPriority);
        }
    }
    sumAll(total, error);
    result.value = total;
    result.error = error;
    return result;
}

}  // namespace ls::ref
