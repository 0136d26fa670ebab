#pragma once
// The public enums where an engine's value enters the plugin: a value cast from an integer that
// names no enumerator would otherwise fall into some branch's default and render (a LightType 7
// lit as a point light of another scale), so each is refused naming its field and the values it
// may take.
#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

void checkMethod(Method m, const std::string& field);
void checkProfile(Profile p, const std::string& field);
void checkLightType(LightType t, const std::string& field);
void checkRangeFalloff(RangeFalloff f, const std::string& field);
void checkMiePhase(MiePhase p, const std::string& field);

}  // namespace lightscatter::detail
