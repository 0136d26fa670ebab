#include "method_registry.h"

namespace ls {

const std::vector<const MethodUnit*>& methodRegistry() {
    static const std::vector<const MethodUnit*> all{
#define LIGHTSCATTER_METHOD(Enum, Type, member) &methodUnit##Enum(),
#define LIGHTSCATTER_METHOD_WITHOUT_SETTINGS(Enum) &methodUnit##Enum(),
#include "lightscatter/methods.inc"
    };
    return all;
}

}  // namespace ls
