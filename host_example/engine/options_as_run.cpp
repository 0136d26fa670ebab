#include "options_as_run.h"

namespace host {

bool honours(lightscatter::Method method, bool lightscatter::MethodInfo::*what) {
    if (method == lightscatter::Method::Auto) return true;  // it picks one that does
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        if (m.method == method) return m.*what;
    return false;
}

RenderOptions asRun(RenderOptions o) {
    if (!honours(o.method, &lightscatter::MethodInfo::noise)) o.custom.noiseAmplitude = 0.0f;
    if (!honours(o.method, &lightscatter::MethodInfo::simplifiedModel))
        o.custom.lightModel = lightscatter::LightModel::Full;
    return o;
}

}  // namespace host
