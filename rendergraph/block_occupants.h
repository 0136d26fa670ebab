#pragma once
// What last touched each part of one memory block, for the first uses of aliased resources: the
// union of the states (pipeline stages, access) of every resource whose range meets a query range,
// in logarithmic time per query (a segment tree over the ranges' end points), so that a graph of
// many chains sharing one block compiles in time linear in its resources, not quadratic (issue
// #22: `budget --lights` of 3,000 lights took 26 s).
#include <vulkan/vulkan.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace rg::detail {

class BlockOccupants {
  public:
    struct Occupant {
        VkDeviceSize begin, end;  // [begin, end) within the block
        VkPipelineStageFlags2 stages;
        VkAccessFlags2 access;
    };
    explicit BlockOccupants(const std::vector<Occupant>& occupants);
    // The union of the states of the occupants that overlap [begin, end).
    std::pair<VkPipelineStageFlags2, VkAccessFlags2> meeting(VkDeviceSize begin,
                                                             VkDeviceSize end) const;
    // How many occupants overlap [begin, end).
    size_t count(VkDeviceSize begin, VkDeviceSize end) const;

  private:
    struct Node {
        VkPipelineStageFlags2 coverStages = 0, subStages = 0;  // covering the node; in its subtree
        VkAccessFlags2 coverAccess = 0, subAccess = 0;
    };
    size_t from(VkDeviceSize begin) const;
    size_t to(VkDeviceSize end) const;
    void insert(size_t node, size_t lo, size_t hi, size_t a, size_t b, const Occupant& o);
    void query(size_t node, size_t lo, size_t hi, size_t a, size_t b,
               std::pair<VkPipelineStageFlags2, VkAccessFlags2>& out) const;
    std::vector<VkDeviceSize> points_, begins_, ends_;
    size_t leaves_ = 1;
    std::vector<Node> nodes_;
};

}  // namespace rg::detail
