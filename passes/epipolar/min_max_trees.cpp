#include "min_max_trees.h"

namespace ls {

uint32_t treeLevels(uint32_t shadowMapSize) {
    uint32_t levels = 0;
    while ((2u << levels) <= shadowMapSize) ++levels;
    return levels;  // level l (1..levels) has shadowMapSize >> l nodes
}

bool treesFit(uint32_t shadowMapSize) {
    return treeLevels(shadowMapSize) >= 2;
}

}  // namespace ls
