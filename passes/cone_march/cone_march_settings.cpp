// Cone-march's field table (seed 003).
#include "cone_march_method.h"
#include "shared/settings_table.h"

namespace ls {

std::vector<SettingsField> ConeMarchMethod::settingsFields() const {
    using C = lightscatter::ConeMarchSettings;
    FieldsOf<C> f("coneMarch", &Settings::coneMarch);
    f.whole("samples", &C::samples, 1, 4096, "").former({"coneSamples"}).doc("samples per pixel");
    f.boolean("limited", &C::limited)
        .former({"coneLimited"})
        .doc("only the ray's part in the cone and range (false: the whole ray)");
    f.boolean("jitter", &C::jitter).former({"coneJitter"}).doc("jittered sample offsets");
    return f.take();
}

}  // namespace ls
