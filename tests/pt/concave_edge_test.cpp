// A vertex on a concave edge (where a floor meets a wall) is lit like its neighbours. The ray
// origin is lifted along the hit surface's normal, which leaves it exactly on the other surface;
// rays leaving a vertex must skip that surface (Integrator::leave_tnear). Before, every such
// vertex was in shadow: in a box room seen from its symmetry axis, the edges project onto the
// image diagonals and pixel-centre rays land on them exactly (the Cornell box lost 13 of 1024
// pixels' light, 2 % of its image mean, against Mitsuba 3: docs/pathtracer.md "Leaving a surface").
#include <gtest/gtest.h>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

TEST(ConcaveEdge, EveryPixelOfAnEmptyRoomUnderAPointLightIsLit) {
  // An empty convex room: a point light inside reaches every surface point unoccluded, so a pixel
  // with no direct light is a ray that stopped at the surface it left from.
  Scene s;
  const uint32_t m = test::add_material(s, test::lambertian(vec3(0.7f)));
  test::add_room(s, vec3(-1.0f, 0.0f, -1.0f), vec3(1.0f, 2.0f, 4.0f), m);
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.3f, 1.2f, 0.5f);
  l.intensity = 5.0f;
  s.lights.push_back(l);
  // On the room's symmetry axis: the four long edges (x = +-1, y = 0 or 2) project exactly onto
  // the image diagonals.
  s.camera = test::look_at(vec3(0.0f, 1.0f, 3.0f), vec3(0.0f, 1.0f, 0.0f), vec3(0, 1, 0), 1.2f);
  test::finish(s);
  PtSettings ps;
  ps.width = ps.height = 32;
  const PathTracer pt(s, ps);
  Accumulator acc(32, 32);
  pt.render(acc, 1);
  const Image direct = acc.mean(kDirect);
  int dark = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if (!(direct.rgb(x, y).g > 0.0f)) {
        ++dark;
        ADD_FAILURE() << "pixel (" << x << ", " << y << ") has no direct light";
      }
  EXPECT_EQ(dark, 0);
}

}  // namespace
}  // namespace vct::pt
