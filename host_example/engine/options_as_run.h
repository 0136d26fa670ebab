#pragma once
// What a frame runs of its options: only some methods sample seed 002's noise and only some run
// seed 004's simplified model (auto picks one that does); the others run without them. The viewer
// runs its options so, and its "save settings" writes what ran, so that the command its message
// gives reads the file back (--method M with the noise on is refused where M ignores it).
#include <lightscatter/lightscatter.h>
#include "engine_renderer.h"

namespace host {

// Whether a method honours a setting MethodInfo names (`what`: &MethodInfo::noise, ...); Auto
// picks one that does.
bool honours(lightscatter::Method method, bool lightscatter::MethodInfo::*what);

// `o` with the noise's amplitude 0 and the full light model where its method ignores them.
RenderOptions asRun(RenderOptions o);

}  // namespace host
