#include "method_registry.h"

#include "analytic/analytic_method.h"
#include "beam_tree_hybrid/beam_tree_methods.h"
#include "brute_force/brute_force_method.h"
#include "cone_march/cone_march_method.h"
#include "epipolar/epipolar_method.h"
#include "froxels/froxels_method.h"
#include "planes/planes_method.h"

namespace ls {

const std::vector<const MethodUnit*>& methodRegistry() {
    static const EpipolarMethod epipolar;
    static const BruteForceMethod bruteForce;
    static const AnalyticMethod analytic;
    static const ConeMarchMethod coneMarch;
    static const PlanesMethod planes;
    static const BeamTreeAnalyticMethod beamTreeAnalytic;
    static const BeamTreeSamplingMethod beamTreeSampling;
    static const FroxelsMethod froxels;
    static const std::vector<const MethodUnit*> all{
        &epipolar, &bruteForce,       &analytic,         &coneMarch,
        &planes,   &beamTreeAnalytic, &beamTreeSampling, &froxels};
    return all;
}

const MethodUnit* findMethod(const std::string& name) {
    for (const MethodUnit* m : methodRegistry())
        if (name == m->name()) return m;
    return nullptr;
}

}  // namespace ls
