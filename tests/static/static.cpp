// Compile-time tests: if this file compiles, the exact tier ran in constant evaluation on
// touching and degenerate cases (the filter cannot decide those, so the expansion and dyadic
// stages ran at compile time too). Also: point + point does not compile, and no project macro
// leaks out of `import incidence;`.
#include <catch2/catch_test_macros.hpp>
#include <array>
#include <type_traits>
#include <cstddef>
import incidence;
import incidence.detail;
#include "testkit/mesh_fixtures.hpp"
#include "testkit/polygon_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/polygon3_fixtures.hpp"

using namespace incidence;

namespace {
constexpr triangle3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
constexpr aabb3 B{{0, 0, 0}, {1, 1, 1}};
constexpr sphere3 S{{0, 0, 0}, 1};
constexpr double tiny = 0x1p-1074;
constexpr double huge = 0x1p1000;

// ray-triangle: interior, edge, vertex, coplanar, degenerate triangle, miss
static_assert(intersects(ray3{{0.25, 0.25, 1}, {0, 0, -1}}, T));
static_assert(intersects(ray3{{0.5, 0, 1}, {0, 0, -1}}, T));
static_assert(intersects(ray3{{0, 1, 1}, {0, 0, -1}}, T));
static_assert(intersects(ray3{{-1, 0.5, 0}, {1, 0, 0}}, T));
static_assert(!intersects(ray3{{-1, 0.5, 0}, {-1, 0, 0}}, T));
static_assert(intersects(ray3{{1, 1, 1}, {-1, -1, -1}}, triangle3{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}));
static_assert(!intersects(ray3{{0.5, 0.5000000000000001, 1}, {0, 0, -1}}, T));
static_assert(intersects(T, ray3{{0.5, 0.5, 1}, {0, 0, -1}}));   // reversed order, hypotenuse
static_assert(intersects(ray3{{tiny, tiny, 1}, {0, 0, -1}}, T)); // subnormal, interior
static_assert(intersects(ray3{{0.5 * huge, 0, huge}, {0, 0, -huge}}, triangle3{{0, 0, 0}, {huge, 0, 0}, {0, huge, 0}}));
// segment-triangle
static_assert(intersects(segment3{{0.25, 0.25, 1}, {0.25, 0.25, 0}}, T));
static_assert(!intersects(segment3{{0.25, 0.25, 1}, {0.25, 0.25, 0.5}}, T));
// ray-box
static_assert(intersects(B, ray3{{-1, 1, 1}, {1, 0, 0}}));  // along an edge
static_assert(intersects(B, ray3{{2, 1, 0}, {-1, -1, 0}})); // touching an edge only
static_assert(!intersects(B, ray3{{2.0000000000000004, 1, 0}, {-1, -1, 0}}));
// near 2^1024, where a slab parameter overflows (no rounded-parameter stage in constant evaluation)
static_assert(intersects(aabb3{{-0x1p1023, -1, -1}, {-0x1p1022, 1, 1}}, ray3{{0x1p1023, 0, 0}, {-1, 0, 0}}) &&
              !intersects(aabb3{{-0x1p1023, -1, -1}, {-0x1p1022, 1, 1}}, ray3{{0x1p1023, 2, 0}, {-1, 0, 0}}));
// box-triangle: touching a corner, one ulp off it, plane through the far corner, edge axis, flat box
static_assert(intersects(B, triangle3{{1, 1, 1}, {2, 1, 1}, {1, 2, 2}}));
static_assert(!intersects(B, triangle3{{1, 1, 1.0000000000000002}, {2, 1, 2}, {1, 2, 2}}));
static_assert(intersects(triangle3{{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, B)); // reversed order
static_assert(!intersects(B, triangle3{{1.5, -1, 0.5}, {3, 0.5, 0.5}, {1.5, 2, 0.5}}));
static_assert(intersects(aabb3{{0.25, 0.25, 0}, {0.25, 0.25, 0}}, T));
static_assert(intersects<conservative>(B, triangle3{{1, 1, 1}, {2, 1, 1}, {1, 2, 2}}));
static_assert(intersects<approximate>(B, triangle3{{0.5, 0.5, 0.5}, {3, 0, 0}, {0, 3, 0}}));
// box-segment and box-line: touching an edge, one ulp off, ending on a face, behind the origin
static_assert(intersects(B, segment3{{2, 1, 0}, {0, -1, 0}}));
static_assert(!intersects(B, segment3{{-1, 0.5, 0.5}, {-0x1p-1074, 0.5, 0.5}}));
static_assert(intersects(segment3{{-1, 0.5, 0.5}, {0, 0.5, 0.5}}, B));
static_assert(intersects(B, line3{{5, 0.5, 0.5}, {1, 0, 0}}));
static_assert(!intersects(B, line3{{-1, 1.0000000000000002, 1}, {1, 0, 0}}));
static_assert(intersects(line3{{2, 1, 0}, {-1, -1, 0}}, B));
// planes: touching a box corner, one ulp off, an end point, a triangle vertex
static_assert(intersects(B, plane3{{1, 1, 1}, 3}));
static_assert(!intersects(plane3{{1, 1, 1}, 3.0000000000000004}, B));
static_assert(intersects(plane3{{0, 0, 1}, 1}, segment3{{0, 0, 0}, {5, 5, 1}}));
static_assert(!intersects(segment3{{0, 0, 0}, {5, 5, 0.9999999999999999}}, plane3{{0, 0, 1}, 1}));
static_assert(intersects(plane3{{0, 0, 1}, 0}, T));
static_assert(!intersects(plane3{{0, 0, 1}, 0x1p-1074}, T));
// OBB pairs: a box rotated 45 degrees about z (axes (1, 1, 0) and (-1, 1, 0), a parallelepiped)
constexpr obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
static_assert(intersects(D, point3{2, 0, 0})); // a corner
static_assert(!intersects(point3{2.0000000000000004, 0, 0}, D));
static_assert(intersects(D, obb3{{3, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}})); // corner on a face
static_assert(!intersects(D, obb3{{3.0000000000000004, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}}));
static_assert(intersects(aabb3{{2, -1, -1}, {3, 1, 1}}, D));
static_assert(!intersects<aggressive>(D, aabb3{{2.0000000000000004, -1, -1}, {3, 1, 1}}));
static_assert(intersects(D, segment3{{2, 0, -5}, {2, 0, 5}})); // along an edge
static_assert(intersects(D, ray3{{3, 0, 0}, {-1, 0, 0}}));
static_assert(!intersects(ray3{{3, 0, 0}, {1, 0, 0}}, D));
static_assert(intersects(line3{{2, 0, 7}, {0, 0, 1}}, D));
static_assert(!intersects(D, line3{{2.0000000000000004, 0, 7}, {0, 0, 1}}));
static_assert(intersects(D, triangle3{{2, 0, 0}, {3, 1, 0}, {3, -1, 0}}));
static_assert(intersects(D, plane3{{1, 0, 0}, 2}));
static_assert(!intersects(plane3{{1, 0, 0}, 2.0000000000000004}, D));
static_assert(intersects<conservative>(D, plane3{{1, 1, 0}, 2}));
static_assert(intersects<approximate>(D, point3{0.5, 0.5, 0.5}));
// containment by the boxes and the ball: D holds the unit box turned back, the box tangent inside a
// ball, a ball tangent to D's top face
static_assert(contains(D, aabb3{{-1, 0, -1}, {0, 1, 1}}) && !contains(D, aabb3{{-1, 0, -1}, {0, 1.0000000000000002, 1}}));
static_assert(contains(aabb3{{-2, -2, -1}, {2, 2, 1}}, D) && !contains(aabb3{{-2, -2, -1}, {2, 2, 0.9999999999999999}}, D));
static_assert(contains(D, obb3{{0.5, 0.5, 0}, D.axes, {0.5, 1, 1}}) &&
              !contains(D, obb3{{0.5, 0.5, 0}, D.axes, {0.5, 1.0000000000000002, 1}}));
static_assert(contains(D, segment3{{2, 0, 1}, {-2, 0, -1}}) && contains(D, triangle3{{2, 0, 1}, {0, 2, 1}, {0, 0, -1}}));
static_assert(contains(aabb3{{0, 0, 0}, {1, 1, 1}}, triangle3{{0, 0, 0}, {1, 1, 1}, {1, 0, 0}}) &&
              !contains(aabb3{{0, 0, 0}, {1, 1, 1}}, segment3{{0, 0, 0}, {1, 1, 1.0000000000000002}}));
static_assert(contains(sphere3{{0, 0, 0}, 3}, aabb3{{-1, -2, -2}, {1, 2, 2}}) &&
              contains(aabb3{{0, 0, 0}, {2, 2, 2}}, sphere3{{1, 1, 1}, 1}));
static_assert(intersects(aabb3{{0, 0, 0}, {1, 1, 1}}, sphere3{{2, 3, 3}, 3}) &&
              !intersects(aabb3{{0, 0, 0}, {1, 1, 1}}, sphere3{{2, 3, 3}, 0x1.7ffffffffffffp+1}));
static_assert(contains(D, sphere3{{0, 0, 0}, 1}) && !contains(D, sphere3{{0, 0, 0.5}, 0.5000000000000001}));
static_assert(contains(sphere3{{0, 0, 0}, 3}, obb3{{0, 0, 0}, {vec3{0, 1, 0}, vec3{0, 0, -1}, vec3{1, 0, 0}}, {1, 2, 2}}));
// a box in a tetrahedron: the unit cube's far corner on the face x + y + z = 3, then that face moved in
// one ulp; a flat square in a flat tetrahedron (its hull the triangle x, y >= 0, x + y <= 2)
constexpr obb3 unit_cube{{0.5, 0.5, 0.5}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {0.5, 0.5, 0.5}};
static_assert(contains(tetrahedron3{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, unit_cube) &&
              !contains(tetrahedron3{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 0x1.7ffffffffffffp+1}}, unit_cube));
static_assert(contains(tetrahedron3{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}},
                       obb3{{0.5, 0.5, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {0.5, 0.5, 0}}));
// ray-sphere, spheres, points, boxes
static_assert(intersects(ray3{{-5, 1, 0}, {1, 0, 0}}, S)); // tangent
static_assert(!intersects(ray3{{-5, 1.0000000000000002, 0}, {1, 0, 0}}, S));
static_assert(intersects(sphere3{{0, 0, 0}, 1}, sphere3{{2, 0, 0}, 1})); // tangent balls
static_assert(contains(sphere3{{0, 0, 0}, 4}, sphere3{{1, 2, 2}, 1}));   // internally tangent
static_assert(intersects(point3{1, 2, 2}, sphere3{{0, 0, 0}, 3}));       // on the sphere
static_assert(!intersects(point3{1, 2, 2.0000000000000004}, sphere3{{0, 0, 0}, 3}));
static_assert(intersects(B, aabb3{{1, 1, 1}, {2, 2, 2}}));
static_assert(covers(aabb3{{0, 0, 0}, {1, 1, 1}}, aabb3{{1, 0, 0}, {2, 1, 1}}, aabb3{{0, 0, 0}, {2, 1, 1}}));
static_assert(squared_distance(B, point3{2, 3, 4}) == 14.0);
static_assert(squared_distance(point3{0, 0, 0}, point3{3, 4, 0}) == 25.0);
static_assert(distance(segment3{{-1, 0, 0}, {1, 0, 0}}, segment3{{0, -1, 2}, {0, 1, 2}}) == 2.0);
// predicates, including the subnormal range
static_assert(orient3d(point3{0, 0, 0}, point3{tiny, 0, 0}, point3{0, tiny, 0}, point3{0, 0, -tiny}) == sign::positive);
static_assert(orient3d(point3{0.1, 0.2, 0.3}, point3{0.2, 0.4, 0.6}, point3{0.3, 0.1, 0.7}, point3{0.1, 0.2, 0.3}) == sign::zero);
static_assert(orient2d(point2{0.5, 0.5}, point2{12, 12}, point2{24, 24}) == sign::zero);
static_assert(incircle(point2{0, 0}, point2{1, 0}, point2{0, 1}, point2{1, 1}) == sign::zero);
// exact values computed at compile time
static_assert(intersection(ray3{{-5, 0, 0}, {2, 0, 0}}, S)->t_enter == 2.0);
static_assert(intersection(ray3{{0.25, 0.25, 1}, {0, 0, -3}}, T)->t == 1.0 / 3.0);
static_assert(intersection(B, ray3{{-1, 0.5, 0.5}, {2, 0, 0}})->t_exit == 1.0);

// point + point must not compile; point - point is a vector.
template <class A, class B>
concept addable = requires(A a, B b) { a + b; };
// the flat pairs: points, lines, rays, segments, planes and triangles against each other
constexpr segment3 G{{0, 0, 0}, {2, 0, 0}};
static_assert(intersects(G, segment3{{2, 0, 0}, {3, 5, 0}}));                    // end to end
static_assert(!intersects(G, segment3{{0x1.0000000000001p1, 0, 0}, {3, 0, 0}})); // collinear, one ulp apart
static_assert(intersects(G, segment3{{1, -1, 0}, {1, 1, 0}}));                   // crossing
static_assert(!intersects(G, segment3{{1, -1, tiny}, {1, 1, tiny}}));            // skew by a subnormal
static_assert(intersects(line3{{0, 0, 0}, {1, 1, 1}}, line3{{huge, huge, 0}, {0, 0, 1}}));
static_assert(!intersects(line3{{0, 0, 0}, {1, 0, 0}}, line3{{0, 1, 0}, {2, 0, 0}})); // parallel
static_assert(intersects(line3{{1, 1, 1}, {1, 2, 3}}, point3{-1, -3, -5}));
static_assert(intersects(line3{{0, 0, 0}, {1, 0, 0}}, ray3{{3, 0, 0}, {0, 1, 5}}));  // ray starts on the line
static_assert(!intersects(line3{{0, 0, 0}, {1, 0, 0}}, ray3{{3, 2, 0}, {0, 1, 0}})); // heads away
static_assert(intersects(line3{{0, 0, 0}, {1, 1, 0}}, segment3{{0, 2, 0}, {1, 1, 0}}));
static_assert(intersects(point3{0, -0.0, 0}, point3{-0.0, 0, 0}));
static_assert(!intersects(point3{-1, -3, -5}, ray3{{1, 1, 1}, {1, 2, 3}})); // behind the origin
static_assert(intersects(point3{4, 2, 6}, G) == false && intersects(point3{2, 0, 0}, G));
static_assert(!intersects(ray3{{1, 0, 0}, {1, 0, 0}}, ray3{{0, 1, 0}, {0, 1, 0}})); // lines cross behind both
static_assert(intersects(ray3{{0, 0, 0}, {1, 0, 0}}, ray3{{5, 0, 0}, {-1, 0, 0}})); // collinear, facing
static_assert(intersects(ray3{{0, 0, 0}, {1, 1, 0}}, segment3{{0, 0, 0}, {0, -4, 0}}));
static_assert(intersects(line3{{0.5, 0, 5}, {0, 0, -1}}, T)); // through an edge
static_assert(!intersects(line3{{0.5, 0x1.0000000000001p-1, 5}, {0, 0, -1}}, T));
static_assert(intersects(point3{0.5, 0.5, 0}, T) && !intersects(point3{0.5, 0.5, tiny}, T));
static_assert(intersects(plane3{{1, 2, 3}, 6}, point3{1, 1, 1}) && !intersects(plane3{{1, 2, 3}, 6}, point3{1, 1, 0x1.0000000000001p0}));
static_assert(intersects(line3{{0, 0, 0}, {1, 0, tiny}}, plane3{{0, 0, 1}, 2})); // nearly parallel still crosses
static_assert(!intersects(plane3{{0, 0, 1}, 2}, ray3{{0, 0, 0}, {1, 1, -1}}));   // heads away
static_assert(intersects(plane3{{0, 0, 1}, 2}, plane3{{0, 0, -3}, -6}));         // the same plane
static_assert(!intersects(plane3{{0, 0, 1}, 2}, plane3{{0, 0, 3}, 0x1.8000000000001p2}));
// tetrahedra (the unit corner tetrahedron Q): every pair, and containment
constexpr tetrahedron3 Q{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
static_assert(intersects(point3{0.5, 0.25, 0.25}, Q) && !intersects(point3{0.5, 0.25, 0x1.0000000000001p-2}, Q));
static_assert(intersects(segment3{{0.5, 0.5, -1}, {0.5, 0.5, 1}}, Q));
static_assert(!intersects(segment3{{0.5, 0x1.0000000000001p-1, -1}, {0.5, 0x1.0000000000001p-1, 1}}, Q));
static_assert(intersects(Q, ray3{{2, 0, 0}, {-1, 0, 0}}) && !intersects(Q, ray3{{2, 0, 0}, {1, 0, 0}}));
static_assert(intersects(line3{{0, 0, 1}, {1, 1, 0}}, Q) && !intersects(line3{{0, 0, 0x1.0000000000001p0}, {1, 1, 0}}, Q));
static_assert(intersects(plane3{{0, 0, 1}, 1}, Q) && !intersects(plane3{{0, 0, 1}, 0x1.0000000000001p0}, Q));
static_assert(intersects(Q, triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, 0.5}})); // cuts it, no vertex inside
static_assert(!intersects(Q, triangle3{{-1, -1, -tiny}, {3, -1, -tiny}, {-1, 3, -tiny}}));
static_assert(intersects(Q, tetrahedron3{{1, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0, 1}})); // a shared vertex
static_assert(!intersects(Q, tetrahedron3{{0x1.0000000000001p0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0, 1}}));
static_assert(intersects(aabb3{{0.25, 0.25, 0.5}, {2, 2, 2}}, Q) && !intersects(aabb3{{0.25, 0.25, 0x1.0000000000001p-1}, {2, 2, 2}}, Q));
static_assert(intersects(obb3{{2, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}}, Q));
static_assert(intersects<conservative>(Q, point3{0.25, 0.25, 0.25}) && !intersects<aggressive>(Q, point3{2, 2, 2}));
static_assert(contains(Q, segment3{{0, 0, 0}, {0.5, 0.25, 0.25}}) && !contains(Q, segment3{{0, 0, 0}, {0.5, 0.5, 0.5}}));
static_assert(contains(aabb3{{0, 0, 0}, {1, 1, 1}}, Q) && contains(Q, aabb3{{0, 0, 0}, {0.25, 0.25, 0.5}}));
static_assert(tetrahedron3{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}}.is_degenerate() && !Q.is_degenerate());
static_assert(!tetrahedron3::make(Q.a, Q.b, Q.c, point3{1, 1, 0}).has_value() && tetrahedron3::make(Q.a, Q.b, Q.c, Q.d).has_value());
// a closed mesh (support/mesh_fixtures.hpp: the unit cube, and the cube with a dented top), inside
// by exact crossing parity
static_assert(intersects(support::cube, point3{0.3, 0.3, 0.3}) && !intersects(support::cube, point3{0x1.0000000000001p0, 0.5, 0.5}));
static_assert(intersects(support::dented, point3{0.5, 0.5, 0.2}) && !intersects(support::dented, point3{0.5, 0.5, 0.5}));
static_assert(intersects(segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.25}}, support::dented));
static_assert(!intersects(segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0x1.0000000000001p-2}}, support::dented));
static_assert(intersects(support::cube, plane3{{0, 0, 1}, 1}) && !intersects(support::cube, plane3{{0, 0, 1}, 0x1.0000000000001p0}));
static_assert(intersects(support::dented, Q) && contains(support::dented, point3{0.5, 0.5, 0.2}));
// contains(mesh, segment): the segment split where it meets the surface, each piece decided at its
// exact midpoint (up to the top face; across the dent)
static_assert(contains(support::cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 1}}) &&
              !contains(support::dented, segment3{{0.1, 0.5, 0.9}, {0.9, 0.5, 0.9}}));
// contains(mesh, triangle): the sweep by chords from a vertex; on the top face (every vertex on the
// surface: the chords' lines followed from outside), under the dent up to its apex, across the dent
static_assert(contains(support::cube, triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}) &&
              contains(support::dented, triangle3{{0, 0, 0}, {1, 1, 0}, {0.5, 0.5, 0.25}}) &&
              !contains(support::dented, triangle3{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.5, 0.9, 0.5}}));
// contains(mesh, box): no triangle reaches the box's interior (or those that do cover their plane
// an even number of times there), and its centre's parity; the cube's own box, under the dent up to
// its apex and one ulp above, a flat box on the top face (two triangles)
static_assert(contains(support::cube, aabb3{{0, 0, 0}, {1, 1, 1}}) && contains(support::dented, aabb3{{0, 0, 0}, {1, 1, 0.25}}) &&
              !contains(support::dented, aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p-2}}) &&
              contains(support::cube, aabb3{{0, 0, 1}, {1, 1, 1}}));
// a half-space set against a mesh: inside it (no triangle meets it: the parity of its vertex), above
// the dent, a flat one on the dent's apex and one ulp above
static_assert(intersects(kdop<6>{{0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}}, support::cube) &&
              !intersects(support::dented, kdop<6>{{0.45, 0.45, 0.5}, {0.55, 0.55, 0.9}}));
static_assert(intersects(kdop<6>{{0.5, 0.5, 0.25}, {0.5, 0.5, 0.9}}, support::dented) &&
              !intersects(kdop<6>{{0.5, 0.5, 0x1.0000000000001p-2}, {0.5, 0.5, 0.9}}, support::dented));
static_assert(intersects(support::polyhedron_fixtures::unit_cube_cut, support::dented) &&
              !intersects(support::cube, convex_polyhedron3{{plane3{{1, 0, 0}, -0x1p-1074}}, 1}));
// a polygon with a hole and a C shape (support/polygon_fixtures.hpp), inside by exact crossing
// parity; make() decides simplicity exactly
static_assert(intersects(point2{0.5, 3}, support::frame) && !intersects(point2{2, 2}, support::frame));
static_assert(intersects(point2{1, 2}, support::frame) && !intersects(point2{0x1.0000000000001p2, 2}, support::frame));
static_assert(intersects(support::frame, segment2{{1.5, 1.5}, {2.5, 3.5}}) &&
              !intersects(support::frame, segment2{{1.5, 1.5}, {2.5, 2.5}}));
static_assert(!intersects(support::c_shape, ray2{{2, 2}, {1, 0}}) && intersects(support::c_shape, ray2{{2, 2}, {-1, 0}}));
static_assert(intersects(line2{{0, 8}, {1, -1}}, support::frame) && !intersects(line2{{0, 0x1.0000000000001p3}, {1, -1}}, support::frame));
static_assert(intersects(support::frame, support::c_shape) && contains(support::c_shape, point2{3, 3.5}));
static_assert(polygon2::make(support::frame_vertices, support::frame_ends).has_value());
static_assert(polygon2::make(support::c_vertices, std::span<const std::uint32_t, 1>(support::frame_ends.data(), 1)).error().code ==
              errc::index_out_of_range);
// k-DOPs (support/kdop_fixtures.hpp): the generalised slab test
static_assert(intersects(support::corner_cut, point3{1, 1, 0.5}) && !intersects(support::corner_cut, point3{1, 1, 0x1.0000000000001p-1}));
static_assert(intersects(support::corner_cut, ray3{{3, -1, 0.5}, {-1, 1, 0}}) &&
              !intersects(support::corner_cut, ray3{{2, 2, 2}, {1, 1, 1}}));
static_assert(intersects(segment3{{2, 2, 0.5}, {1, 1, 0.5}}, support::corner_cut) &&
              !intersects(support::empty14, segment3{{-5, -5, -5}, {5, 5, 5}}));
static_assert(intersects(support::corner_cut, line3{{1, 1, 0.5}, {1, -1, 0}}) &&
              !intersects(support::corner_cut, line3{{1, 1, 1}, {1, -1, 0}}));
static_assert(intersects(support::edge_cut, point3{1, 0.5, 0.25}) && contains(support::unit26, point3{0, 0, 0}));
// two k-DOPs, a box and a k-DOP: slab overlap, then the Farkas certificates (x + y + z <= 5/2
// against x, y, z >= 7/8 in every slab-overlapping pair below)
static_assert(!intersects(support::corner_cut, kdop<14>{{0.875, 0.875, 0.875, -5, -5, -5, -5}, {2, 2, 2, 6, 5, 5, 5}}));
static_assert(intersects(support::corner_cut, kdop<14>{{0.8125, 0.8125, 0.8125, -5, -5, -5, -5}, {2, 2, 2, 6, 5, 5, 5}}));
static_assert(!intersects(support::edge_cut, aabb3{{0.875, 0.875, 0}, {2, 2, 1}}) &&
              intersects(aabb3{{0.75, 0.75, 0}, {2, 2, 1}}, support::edge_cut));
static_assert(intersects(support::edge_cut, support::corner_cut) && !intersects(support::empty14, support::unit6));
static_assert(contains(support::corner_cut, aabb3{{0, 0, 0}, {1, 1, 0.5}}) &&
              !contains(support::corner_cut, aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p-1}}));
// convex polyhedra and frustums (support/polyhedron_fixtures.hpp): the generalised slab test on
// their half-spaces
namespace ph = support::polyhedron_fixtures;
static_assert(intersects(ph::unit_cube_cut, point3{1, 1, 0.5}) && !intersects(ph::unit_cube_cut, point3{1, 1, 0x1.0000000000001p-1}));
static_assert(intersects(segment3{{2, 2, 0.5}, {1, 1, 0.5}}, ph::unit_cube_cut) &&
              !intersects(ph::empty_slab, segment3{{-5, -5, -5}, {5, 5, 5}}));
static_assert(intersects(ph::unit_cube_cut, ray3{{2, 0.5, 1}, {-1, 0, 0}}) &&
              !intersects(ph::unit_cube_cut, ray3{{2, 0.5, 0x1.0000000000001p0}, {-1, 0, 0}}));
static_assert(intersects(ph::half_space, line3{{1, 0, 0}, {-0x1p-1074, 1, 1}}) && !intersects(ph::half_space, line3{{1, 0, 0}, {0, 1, 1}}));
static_assert(contains(ph::unit_cube_cut, segment3{{0, 0, 0}, {1, 1, 0.5}}) && !contains(ph::unit_cube_cut, point3{1, 1, 1}));
static_assert(intersects(ph::integer_frustum, point3{1, 1, 1}) && !intersects(ph::integer_frustum, point3{0x1.0000000000001p0, 1, 1}));
static_assert(intersects(ph::integer_frustum, segment3{{0, 0, 0}, {1, 1, 1}}) &&
              !intersects(ph::integer_frustum, segment3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}));
static_assert(intersects(ph::integer_frustum, ray3{{0, 0, 0}, {1, 1, 1}}) &&
              !intersects(ray3{{8, 0, 0x1.0000000000001p2}, {-1, 0, 0}}, ph::integer_frustum));
static_assert(intersects(line3{{0, 4, 4}, {1, 0, 0}}, ph::integer_frustum) &&
              !intersects(ph::integer_frustum, line3{{0, 0x1.0000000000001p2, 4}, {1, 0, 0}}));
static_assert(contains(ph::integer_frustum, segment3{{1, 1, 1}, {-4, -4, 4}}) && frustum3::make(ph::integer_frustum.planes).has_value());
// a box against them: the vertex test of both shapes' planes
static_assert(intersects(aabb3{{0.5, 1, 1}, {2, 2, 2}}, ph::unit_cube_cut) &&
              !intersects(aabb3{{0x1.0000000000001p-1, 1, 1}, {2, 2, 2}}, ph::unit_cube_cut));
static_assert(!intersects(ph::roof, aabb3{{-1, 0, 0.5}, {1, 1, 1}}) && intersects(ph::roof, aabb3{{-1, 0, 0}, {1, 1, 1}}));
static_assert(intersects(ph::integer_frustum, aabb3{{4, 4, 4}, {5, 5, 5}}) &&
              !intersects(ph::integer_frustum, aabb3{{4, 4, 0x1.0000000000001p2}, {5, 5, 5}}));
static_assert(!intersects(aabb3{{4.5, 0, 3}, {5, 0, 4.75}}, ph::integer_frustum) &&
              method::aabb_frustum_culling(aabb3{{4.5, 0, 3}, {5, 0, 4.75}}, ph::integer_frustum));
static_assert(contains(ph::integer_frustum, aabb3{{-1, -1, 1}, {1, 1, 1}}) && contains(ph::unit_cube_cut, aabb3{{0, 0, 0}, {1, 1, 0.5}}));
// a plane against them: the set's points on both sides (vertices, the roof's ridge line, a half-space's plane)
static_assert(intersects(ph::unit_cube_cut, plane3{{1, 1, 1}, 2.5}) &&
              !intersects(plane3{{1, 1, 1}, 0x1.4000000000001p1}, ph::unit_cube_cut));
static_assert(intersects(ph::roof, plane3{{0, 0, 1}, 0}) && !intersects(ph::roof, plane3{{0, 0, 1}, 0x1p-1074}));
static_assert(intersects(ph::half_space, plane3{{-2, 0, 0}, 2}) && !intersects(ph::half_space, plane3{{1, 0, 0}, 0x1p-1074}));
static_assert(intersects(ph::integer_frustum, plane3{{1, 1, 0}, 8}) &&
              !intersects(ph::integer_frustum, plane3{{1, 1, 0}, 0x1.0000000000001p3}));
// two half-space sets: a face with the other beyond it, a point inside both, the feasibility test
static_assert(intersects(ph::roof, convex_polyhedron3{{plane3{{0, 0, -1}, 0}}, 1}) &&
              !intersects(ph::roof, convex_polyhedron3{{plane3{{0, 0, -1}, -0x1p-1074}}, 1}));
static_assert(intersects(ph::unit_cube_cut, ph::unit_cube_cut) && !intersects(ph::empty_slab, ph::half_space));
static_assert(intersects(ph::half_space, ph::integer_frustum) &&
              !intersects(convex_polyhedron3{{plane3{{0, 0, -1}, -0x1.0000000000001p2}}, 1}, ph::integer_frustum));
static_assert(intersects(support::corner_cut, plane3{{1, 1, 1}, 2.5}) &&
              !intersects(plane3{{1, 1, 1}, 0x1.4000000000001p1}, support::corner_cut));
// a half-space set against a k-DOP: the k-DOP's slabs as half-spaces, the test of two sets
static_assert(intersects(ph::unit_cube_cut, kdop<14>{{0.5, 0.5, 0.5, 2.5, -5, -5, -5}, {1, 1, 1, 3, 5, 5, 5}}) &&
              !intersects(kdop<14>{{0.5, 0.5, 0.5, 0x1.4000000000001p1, -5, -5, -5}, {1, 1, 1, 3, 5, 5, 5}}, ph::unit_cube_cut));
static_assert(intersects(kdop<6>{{4, 4, 4}, {5, 5, 5}}, ph::integer_frustum) &&
              !intersects(ph::integer_frustum, kdop<6>{{4, 4, 0x1.0000000000001p2}, {5, 5, 5}}));
// two frustums: the integer frustum reflected through its far corner (x -> 2c - x) touches it there;
// through a point 2^-38 beyond that corner, it misses
static_assert(intersects(ph::integer_frustum, ph::reflected(ph::integer_frustum, {4, 4, 4})) &&
              !intersects(ph::reflected(ph::integer_frustum, {0x1.0000000001p2, 4, 4}), ph::integer_frustum));
// a triangle against a half-space set: a large triangle whose edges miss the set (its section lies
// inside), on a face and one ulp beyond; a corner on the cut face and one ulp off
static_assert(intersects(ph::unit_cube_cut, ph::wide_triangle(0.5)) && intersects(ph::wide_triangle(1), ph::unit_cube_cut) &&
              !intersects(ph::unit_cube_cut, ph::wide_triangle(0x1.0000000000001p0)));
static_assert(intersects(ph::integer_frustum, ph::wide_triangle(2)) && intersects(ph::integer_frustum, ph::wide_triangle(4)) &&
              !intersects(ph::wide_triangle(0x1.0000000000001p2), ph::integer_frustum));
static_assert(intersects(support::corner_cut, triangle3{{1, 1, 0.5}, {3, 3, 3}, {3, 2, 3}}) &&
              !intersects(triangle3{{1, 1, 0x1.0000000000001p-1}, {3, 3, 3}, {3, 2, 3}}, support::corner_cut));
static_assert(contains(ph::integer_frustum, triangle3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 4}}) &&
              !contains(support::corner_cut, triangle3{{0, 0, 0}, {1, 1, 0.5}, {1, 1, 1}}));
// a tetrahedron against a half-space set: one holding the set whole (no face meets it: a vertex of
// the set decides), below the set touching it, and one ulp lower
static_assert(intersects(ph::unit_cube_cut, ph::wide_tetrahedron(2)) && intersects(ph::wide_tetrahedron(0), ph::unit_cube_cut) &&
              !intersects(ph::unit_cube_cut, ph::wide_tetrahedron(-0x1p-1074)));
static_assert(intersects(ph::integer_frustum, ph::wide_tetrahedron(5)) &&
              !intersects(ph::wide_tetrahedron(0x1.fffffffffffffp-1), ph::integer_frustum));
static_assert(intersects(support::corner_cut, ph::wide_tetrahedron(2)) &&
              !intersects(ph::wide_tetrahedron(-0x1p-1074), support::corner_cut));
static_assert(contains(ph::integer_frustum, tetrahedron3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 4}, {0, 4, 4}}) &&
              !contains(support::corner_cut, tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));
// a box turned 45 degrees about z against a half-space set: touching along an edge or at a
// corner, and one ulp short; a box that no single plane separates from the set; contains
constexpr std::array<vec3, 3> turned{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}};
static_assert(intersects(ph::unit_cube_cut, obb3{{1.5, 1.5, 0.5}, turned, {0.5, 0.5, 0.5}}) &&
              !intersects(obb3{{1.5, 1.5, 0.5}, turned, {0x1.fffffffffffffp-2, 0.5, 0.5}}, ph::unit_cube_cut));
static_assert(!intersects(ph::roof, obb3{{0, 0.5, 0.75}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 0.5, 0.25}}));
static_assert(intersects(ph::integer_frustum, obb3{{4.5, 4.5, 4.5}, turned, {0.5, 0.5, 0.5}}) &&
              !intersects(obb3{{4.5, 4.5, 4.5}, turned, {0x1.fffffffffffffp-2, 0.5, 0.5}}, ph::integer_frustum));
static_assert(intersects(support::corner_cut, obb3{{1.5, 1.5, 1}, turned, {0.5, 0.5, 0.5}}) &&
              !intersects(support::corner_cut, obb3{{1.5, 1.5, 0x1.0000000000001p0}, turned, {0.5, 0.5, 0.5}}));
static_assert(contains(ph::unit_cube_cut, obb3{{0.5, 0.5, 0.5}, turned, {0.25, 0.25, 0.5}}) &&
              !contains(support::corner_cut, obb3{{0.5, 0.5, 0.5}, turned, {0.25, 0.25, 0x1.0000000000001p-1}}) &&
              contains(ph::integer_frustum, obb3{{0, 0, 2}, turned, {0.5, 0.5, 0}}));
// a planar polygon in space with a hole: a point inside, in the hole, on the hole's edge; a
// segment through the hole and one ending on the polygon; a frustum whose section lies in a hole
namespace pg = support::polygon3_fixtures;
static_assert(intersects(point3{0.5, 0.5, 1}, pg::holed) && !intersects(point3{2, 2, 1}, pg::holed) &&
              intersects(point3{1, 2, 1}, pg::holed));
static_assert(!intersects(pg::holed, segment3{{2, 2, 0}, {2, 2, 2}}) && intersects(pg::holed, segment3{{0.5, 0.5, 0}, {0.5, 0.5, 1}}) &&
              !intersects(pg::holed, segment3{{0.5, 0.5, 0}, {0.5, 0.5, 0x1.fffffffffffffp-1}}));
static_assert(!intersects(ph::integer_frustum, pg::ring) && intersects(ph::integer_frustum, pg::holed));
static_assert(intersects(aabb3{{0.25, 0.25, 0}, {0.75, 0.75, 2}}, pg::holed) &&
              !intersects(aabb3{{1.5, 1.5, 0}, {2.5, 2.5, 2}}, pg::holed));
static_assert(intersects(pg::tilted_l, pg::holed) && intersects(plane3{{0, 0, 1}, 1.5}, pg::tilted_l));
// the same in the plane
static_assert(intersects(segment2{{0, 0}, {2, 0}}, segment2{{2, 0}, {3, 5}}));
static_assert(!intersects(segment2{{0, 0}, {2, 0}}, segment2{{0x1.0000000000001p1, 0}, {3, 0}}));
static_assert(intersects(segment2{{0.1, 0.1}, {0.3, 0.3}}, segment2{{0.1, 0.3}, {0.3, 0.1}}));
static_assert(!intersects(ray2{{1, 0}, {1, 0}}, ray2{{0, 1}, {0, 1}}));
static_assert(intersects(line2{{10, 0}, {1, 0}}, ray2{{5, 1}, {0, -1}}));
static_assert(intersects(line2{{0, 0}, {1, 0}}, line2{{0, 1}, {1, tiny}}));
static_assert(!intersects(line2{{0, 0}, {1, 0}}, line2{{0, 1}, {2, 0}}));
static_assert(intersects(point2{2, 1}, segment2{{0, 0}, {4, 2}}) && !intersects(point2{6, 3}, segment2{{0, 0}, {4, 2}}));
static_assert(intersects(point2{1, 1}, ray2{{1, 1}, {1, 2}}) && !intersects(point2{-1, -3}, ray2{{1, 1}, {1, 2}}));
static_assert(intersects(line2{{1, 1}, {1, 2}}, point2{-1, -3}));
static_assert(intersects(point2{0, -0.0}, point2{-0.0, 0}));
static_assert(intersects(line2{{0, 0}, {1, 1}}, segment2{{0, 2}, {1, 1}}));
static_assert(!intersects(ray2{{0, 0}, {1, 1}}, segment2{{-1, -1}, {-0.5, -0.5}}));
static_assert(!addable<point3, point3>);
static_assert(addable<point3, vec3>);
static_assert(std::is_same_v<decltype(point3{} - point3{}), vec3>);
static_assert(!addable<point2, point2>);
} // namespace

// Module hygiene: no macro from the library's implementation is visible here.
#if defined(INCIDENCE_EXPORT) || defined(BOOST_OUTCOME_V2_NAMESPACE) || defined(BOOST_MP_CXX14_CONSTEXPR)
#error "a macro leaked out of import incidence;"
#endif

namespace {
// The same kind of cases evaluated with inputs the compiler cannot see through: at run time the
// exact tier takes the same filter -> expansion -> dyadic path, and must give the same answers
// as in constant evaluation (the expected values are pinned by static_assert below).
double opaque(double x) {
    volatile double v = x;
    return v;
}
template <bool Runtime>
constexpr std::array<bool, 12> cases() {
    auto v = [](double x) {
        if constexpr (Runtime) return opaque(x);
        else return x;
    };
    const triangle3 t{{v(0), v(0), v(0)}, {v(1), v(0), v(0)}, {v(0), v(1), v(0)}};
    return {intersects(ray3{{v(0.5), v(0), v(1)}, {v(0), v(0), v(-1)}}, t),
            intersects(ray3{{v(-1), v(0.5), v(0)}, {v(1), v(0), v(0)}}, t),
            !intersects(ray3{{v(0.5), v(0.5000000000000001), v(1)}, {v(0), v(0), v(-1)}}, t),
            intersects(ray3{{v(tiny), v(tiny), v(1)}, {v(0), v(0), v(-1)}}, t),
            intersects(segment3{{v(0.25), v(0.25), v(1)}, {v(0.25), v(0.25), v(0)}}, t),
            intersects(aabb3{{v(0), v(0), v(0)}, {v(1), v(1), v(1)}}, ray3{{v(2), v(1), v(0)}, {v(-1), v(-1), v(0)}}),
            !intersects(aabb3{{v(0), v(0), v(0)}, {v(1), v(1), v(1)}}, ray3{{v(2.0000000000000004), v(1), v(0)}, {v(-1), v(-1), v(0)}}),
            intersects(ray3{{v(-5), v(1), v(0)}, {v(1), v(0), v(0)}}, sphere3{{v(0), v(0), v(0)}, v(1)}),
            !intersects(ray3{{v(-5), v(1.0000000000000002), v(0)}, {v(1), v(0), v(0)}}, sphere3{{v(0), v(0), v(0)}, v(1)}),
            contains(sphere3{{v(0), v(0), v(0)}, v(4)}, sphere3{{v(1), v(2), v(2)}, v(1)}),
            orient3d(point3{v(0), v(0), v(0)}, point3{v(tiny), v(0), v(0)}, point3{v(0), v(tiny), v(0)}, point3{v(0), v(0), v(-tiny)}) ==
                sign::positive,
            intersection(ray3{{v(0.25), v(0.25), v(1)}, {v(0), v(0), v(-3)}}, t)->t == 1.0 / 3.0};
}
constexpr auto compile_time = cases<false>();
static_assert(compile_time == std::array<bool, 12>{true, true, true, true, true, true, true, true, true, true, true, true});
} // namespace

TEST_CASE("static: run-time evaluation agrees with the compile-time results", "[static]") {
    const auto run_time = cases<true>();
    for (std::size_t i = 0; i < run_time.size(); ++i) {
        INFO("case " << i);
        CHECK(run_time[i] == compile_time[i]);
    }
}
