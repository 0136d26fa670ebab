// The fields of plane_resolve.frag's push block, written once for both languages (as
// plane_push_fields.h): passes/planes/plane_geometry.h declares PlaneResolvePush with them.
LS_VEC4 tint LS_INIT(
    0.0f);  // rgb: Lin per unit of the channels' sum (the light's and medium's color x range)
LS_VEC4 slab LS_INIT(0.0f);  // x, y: the view depths the planes cover
