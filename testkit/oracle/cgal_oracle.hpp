// The CGAL oracle: plain functions over double arrays, compiled in their own translation unit
// (CGAL headers and `import incidence;` never meet). Every answer is computed with CGAL's
// exact kernel Epeck (exact rationals), or with Epick where the name says so (for timing).
// Balls, not spheres: CGAL's Sphere_3 is a surface, so ball tests use exact squared distances.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace oracle {

// Shewchuk's sign conventions (see incidence::orient3d), computed by CGAL::orientation etc.
int orient2d(const double a[2], const double b[2], const double c[2]);
int orient3d(const double a[3], const double b[3], const double c[3], const double d[3]);
int incircle(const double a[2], const double b[2], const double c[2], const double d[2]);
int insphere(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3]);

bool triangle_is_degenerate(const double a[3], const double b[3], const double c[3]);
bool ray_triangle(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3]);
bool segment_triangle(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3]);
// Closed box [mn, mx] against a non-degenerate triangle (Epeck). A box of full dimension is a CGAL
// Iso_cuboid_3; a flat box (a rectangle, a segment or a point) is tested as CGAL Triangle_3,
// Segment_3 or Point_3 pieces, since CGAL's box predicates assume a solid.
// Closed box against a segment (p, q; p == q is a point) and against the line through p with
// direction d (d != 0), Epeck.
bool box_segment(const double mn[3], const double mx[3], const double p[3], const double q[3]);
bool box_line(const double mn[3], const double mx[3], const double p[3], const double d[3]);
bool box_segment_epick(const double mn[3], const double mx[3], const double p[3], const double q[3]);
bool box_line_epick(const double mn[3], const double mx[3], const double p[3], const double d[3]);
// The plane n . p = offset (n != 0) against a closed box, a segment (p == q: a point) and a
// triangle (Epeck, and Epick for the peers).
bool box_plane(const double mn[3], const double mx[3], const double n[3], double offset);
bool plane_segment(const double n[3], double offset, const double p[3], const double q[3]);
bool plane_triangle(const double n[3], double offset, const double a[3], const double b[3], const double c[3]);
bool box_plane_epick(const double mn[3], const double mx[3], const double n[3], double offset);
bool plane_segment_epick(const double n[3], double offset, const double p[3], const double q[3]);
bool plane_triangle_epick(const double n[3], double offset, const double a[3], const double b[3], const double c[3]);
bool box_triangle(const double mn[3], const double mx[3], const double a[3], const double b[3], const double c[3]);
bool box_triangle_epick(const double mn[3], const double mx[3], const double a[3], const double b[3], const double c[3]);
bool triangle_triangle(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3],
                       const double f[3]); // both non-degenerate (CGAL's precondition)
bool ray_box(const double o[3], const double d[3], const double mn[3], const double mx[3]);
bool box_box(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]);
bool point_in_box(const double p[3], const double mn[3], const double mx[3]);
bool box_contains_box(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]);
bool point_in_ball(const double p[3], const double c[3], double r);
bool ball_ball(const double c1[3], double r1, const double c2[3], double r2);
bool ball_contains_ball(const double c1[3], double r1, const double c2[3], double r2);
bool ray_ball(const double o[3], const double d[3], const double c[3], double r);

// A closed convex set for the LP oracle, every coefficient an input double: the points' convex
// hull plus sum t_g g with lo_g <= t_g <= hi_g (a box: its centre and its axes with |t| <= h; a
// ray: its origin and t >= 0 along d), or the plane normal . x = offset.
struct convex_set {
    struct generator {
        std::array<double, 3> g;
        bool has_lo = false, has_hi = false;
        double lo = 0, hi = 0;
    };
    struct slab { // lo <= n . x <= hi
        std::array<double, 3> n;
        double lo, hi;
    };
    std::vector<std::array<double, 3>> points;
    std::vector<generator> generators;
    bool plane = false;
    std::array<double, 3> normal{};
    double offset = 0;
    std::vector<slab> slabs; // further constraints on the point; with no points, generators or plane: the slabs alone (a k-DOP)
    struct halfspace {       // n . x <= offset
        std::array<double, 3> n;
        double offset;
    };
    std::vector<halfspace> halfspaces; // like slabs (a convex polyhedron or a frustum: the half-spaces alone)
};
// Do a and b meet? Exact LP feasibility (CGAL QP_solver over Gmpzf), for every pair of convex
// sets, the OBB, k-DOP and frustum pairs that CGAL's kernel cannot express among them.
// Throws when CGAL's own certificate check rejects every answer (seen for inputs spanning
// 2^-1030 .. 2^1020 together); lp_intersect_verified returns std::nullopt then.
bool lp_intersect(const convex_set& a, const convex_set& b);
std::optional<bool> lp_intersect_verified(const convex_set& a, const convex_set& b);
// Does the ball |x - c| <= |r| meet the set? The exact minimum of |x - c|^2 over it (CGAL's
// QP_solver over Gmpzf, the solution accepted once CGAL's certificate check does), compared with
// r^2 in rationals; std::nullopt when every pricing strategy's answer is rejected.
std::optional<bool> qp_ball_meets(const convex_set& s, const std::array<double, 3>& c, double r);
// Do the sets a and b come within |r1| + |r2| of each other (the sum exact)? The exact minimum of
// |x - y|^2 over x in a and y in b (CGAL's QP_solver over Gmpzf, certificate-checked), in
// rationals; std::nullopt when every pricing strategy's answer is rejected.
std::optional<bool> qp_sets_within(const convex_set& a, const convex_set& b, double r1, double r2 = 0.0);
// Is that ball inside every half-space and slab of s (given by those alone)? n . c + |r| |n| <= bound
// for each side, in rationals.
bool ball_in_rows(const convex_set& s, const std::array<double, 3>& c, double r);

// The signed and the squared distance from a point to a solid (cgal_distance.cpp), exactly: a
// capsule (v: a, b, r; a ball when a = b) by CGAL's squared_distance over Epeck; a convex set of
// the LP oracle (`set`: a box, an OBB, a tetrahedron's points, a k-DOP, a frustum, a convex
// polyhedron) by the exact QP outside and the exact rows (faces) inside; a tetrahedron (v: its
// four vertices); a mesh by CGAL's point-triangle distances and mesh_inside.
struct mesh_data;
struct distance_solid {
    enum kind_t { capsule, rows, tetrahedron, mesh } kind;
    std::vector<double> v;
    convex_set set;
    const mesh_data* mesh_ptr = nullptr;
};
// For the exact value d of the signed (squared) distance of p: is x the correctly rounded d, is
// lo <= d <= hi, and |approx - d| (to double); known false when the QP declined.
struct distance_check {
    bool known = false, rounded = false, enclosed = false;
    double error = 0, value = 0; // value: the exact value to about 200 bits, then truncated to double
    int sign = 0;                // the exact value's sign
};
distance_check check_distance(const distance_solid& s, const std::array<double, 3>& p, bool squared, double x, double lo, double hi,
                              double approx);

// A point, segment, ray, line, plane or triangle (cgal_flat.cpp), for the pairs among them: v holds
// a point's 3 values, a segment's end points, a ray's or line's origin and direction, a plane's
// normal and offset (n . x = offset), a triangle's vertices. Degenerate shapes are their point
// sets: a segment with equal ends, a ray or line with a zero direction is a Point_3, a collinear
// triangle is the Segment_3 between its two farthest vertices (or a point), a plane with a zero
// normal is everything when its offset is 0 and empty otherwise. flat_intersect decides with
// CGAL's do_intersect / has_on over Epeck (CGAL::intersection for a ray against a ray or a line,
// see cgal_flat.cpp); flat_intersect_epick is CGAL's do_intersect over Epick (a peer, for timing).
// Solids too: a tetrahedron (v: its four vertices; coplanar ones are their hull) and a box (v: min
// then max; an inverted box is empty). A solid tetrahedron is CGAL's Tetrahedron_3 and a solid box
// its Iso_cuboid_3; a flat box is its pieces (a rectangle's two triangles, a segment or a point),
// and a coplanar tetrahedron is decided by the exact LP oracle (lp_intersect on the point sets),
// since CGAL's solid predicates assume full dimension.
struct flat {
    enum kind_t { point, segment, ray, line, plane, triangle, tetrahedron, box } kind;
    double v[12];
};
// The same shape as the LP oracle's convex set (a plane with a zero normal has no such form).
convex_set lp_set(const flat& f);
// Is every point of b in a? (b a point, segment, triangle, tetrahedron or box: its vertices.)
bool flat_contains(const flat& a, const flat& b);
bool flat_intersect(const flat& a, const flat& b);
bool flat_intersect_epick(const flat& a, const flat& b);
// The squared distance (squared) or the distance between a point, segment, ray, line or triangle
// and another (cgal_distance.cpp: CGAL's squared_distance over Epeck, degenerate shapes as their
// point sets; the exact QP for a triangle against a segment, ray, line or triangle), checked against
// x, [lo, hi] and approx as check_distance does; known false for other kinds or a declined QP.
distance_check check_flat_distance(const flat& a, const flat& b, bool squared, double x, double lo, double hi, double approx);
// The same distance over Epick, as its users write it (a peer, for timing): sqrt(squared_distance);
// NaN for a triangle (no peer row for the triangle pairs).
double flat_distance_epick(const flat& a, const flat& b);
// The ball |x - c| <= |r| against a flat shape or a solid: CGAL's squared_distance(Point_3, X)
// against r r (exact over Epeck; rounded over Epick, a peer for timing), a coplanar tetrahedron as
// its four faces. (Not CGAL's do_intersect(Sphere_3, X): for a triangle and a tetrahedron it reads
// Sphere_3 as the surface, so a triangle inside the ball does not meet it.)
bool ball_flat(const flat& a, const std::array<double, 3>& c, double r);
bool ball_flat_epick(const flat& a, const std::array<double, 3>& c, double r);
// The ball |x - c| <= |r_inner| within |r_outer| of the flat shape (a capsule's segment): |r_inner|
// <= |r_outer| and the centre within |r_outer| - |r_inner| of it, the difference exact (Epeck).
bool flat_holds_ball(const flat& a, const std::array<double, 3>& c, double r_outer, double r_inner);
// Does the closed segment a b (a = b: a point) come strictly within |r| of c: its squared distance
// from c (CGAL's squared_distance over Epeck) below r r?
bool segment_in_open_ball(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c, double r);
// CGAL's do_intersect itself, also for the ray-ray and line-ray pairs where it is wrong (the
// fixtures show it).
bool flat_do_intersect_cgal(const flat& a, const flat& b);
// Closed triangle meshes (cgal_mesh.cpp): the mesh's point set is its triangles (Epeck) and the
// points inside by crossing parity along a segment to a random far point, decided by
// CGAL::orientation over Epeck (for the embedded closed surfaces the tests
// build, the even-odd rule's inside). mesh_intersect: a triangle meets x (flat_intersect, or the
// LP for a convex set) or x's point `inner` is inside; mesh_mesh_intersect is
// CGAL::Polygon_mesh_processing::do_intersect with the bounded sides' overlap test.
struct mesh_data {
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<unsigned, 3>> t;
};
bool mesh_inside(const mesh_data& m, const std::array<double, 3>& p); // on the surface or inside
bool mesh_intersect(const mesh_data& m, const flat& x);
bool mesh_intersect(const mesh_data& m, const convex_set& x, const std::array<double, 3>& inner);
// x given by half-spaces or slabs (no point of it is at hand): when no triangle meets x, the LP's
// exact rational point of x decides by the same parity, over Epeck.
bool mesh_intersect(const mesh_data& m, const convex_set& x);
// Does one of the triangles of `soup` (no closedness asked) meet x? The LP for each, after an
// exact box and row test that settles most of them.
bool any_triangle_meets(const mesh_data& soup, const convex_set& x);
bool mesh_mesh_intersect(const mesh_data& a, const mesh_data& b);
// Is every point of the segment a b in the mesh's point set (exact breakpoints and midpoints)?
bool mesh_contains_segment(const mesh_data& m, const std::array<double, 3>& a, const std::array<double, 3>& b);
// Is every point of the triangle a b c in it (the traces' vertices, chords between their directions)?
bool mesh_contains_triangle(const mesh_data& m, const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c);
// Is every point of the box lo..hi (lo <= hi) in it (the odd coverage of each plane's cells inside
// the box, then one point's parity; cgal_mesh_box.cpp)? std::runtime_error when no clean parity
// segment or no point off the surface is found.
bool mesh_contains_box(const mesh_data& m, const std::array<double, 3>& lo, const std::array<double, 3>& hi);

// The same in the plane: a point, segment, ray or line (v: a point's 2 values, a segment's end
// points, a ray's or line's origin and direction; degenerate ones are Point_2), CGAL's 2D
// do_intersect / has_on over Epeck (exact rationals where a line or a ray meets a line, ray or
// segment: CGAL's answer is wrong there for large coordinates, see cgal_flat.cpp), and CGAL's
// do_intersect over Epick for timing.
struct flat2 {
    enum kind_t { point, segment, ray, line } kind;
    double v[4];
};
bool flat_intersect(const flat2& a, const flat2& b);
bool flat_intersect_epick(const flat2& a, const flat2& b);
bool flat_do_intersect_cgal(const flat2& a, const flat2& b); // do_intersect itself (wrong past 2^340, cgal_flat.cpp)

// Polygons with holes (cgal_polygon.cpp): rings v[ring_ends[i-1], ring_ends[i]) (ring_ends
// always lists every ring's end). The point set is the edges (flat_intersect) and the points on
// the bounded side (CGAL Polygon_2::bounded_side, Epeck) of an odd number of rings.
// polygon_simple: every ring simple (Polygon_2::is_simple) and no two rings' edges meet.
struct polygon_data {
    std::vector<std::array<double, 2>> v;
    std::vector<unsigned> ring_ends;
};
bool polygon_simple(const polygon_data& g);
bool polygon_intersect(const polygon_data& g, const flat2& x);
bool polygon_polygon_intersect(const polygon_data& a, const polygon_data& b);

// A planar polygon in space (its vertices exactly coplanar): rings as in polygon_data, and the
// coordinate its projection drops. Its triangles (9 doubles each, three of its own vertices): a
// constrained triangulation of the projection with every ring edge a constraint, the faces at odd
// nesting depth kept (the even-odd rule), lifted back to the vertices (cgal_polygon.cpp).
struct polygon3_data {
    std::vector<std::array<double, 3>> v;
    std::vector<unsigned> ring_ends;
    int axis = 2;
};
std::vector<std::array<double, 9>> polygon3_triangles(const polygon3_data& g);
// Containment (cgal_polygon.cpp): a segment in a polygon, by its exact breakpoints with the edges
// and the pieces' exact midpoints (on an edge, or on the bounded side of an odd number of rings);
// a segment or a triangle in a 3D polygon, in its plane (CGAL::orientation) and covered by the
// projection of its triangulation (the segment's pieces' midpoints in a triangle; the triangle's
// area equal to the sum of the areas of its intersections with the triangles, clipped in GMP
// rationals).
bool polygon_contains_segment(const polygon_data& g, const std::array<double, 2>& a, const std::array<double, 2>& b);
bool polygon3_contains_segment(const polygon3_data& g, const std::array<double, 3>& a, const std::array<double, 3>& b);
bool polygon3_contains_triangle(const polygon3_data& g, const std::array<double, 9>& t);

// Is `x` the correctly rounded (nearest, ties to even) value of the exact quantity?
bool is_rounded_ray_triangle_t(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3], double t);
// Same for a segment p -> q: t = (x - p).(q - p) / |q - p|^2 of the first contact.
bool is_rounded_segment_triangle_t(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3], double t);
bool interval_contains_point_box_sqdist(const double p[3], const double mn[3], const double mx[3], bool farthest, double lo, double hi);
bool is_rounded_point_box_sqdist(const double p[3], const double mn[3], const double mx[3], bool farthest, double x);
bool is_rounded_ray_box_t(const double o[3], const double d[3], const double mn[3], const double mx[3], double t_enter, double t_exit);
// For the ray-ball first hit t1 (irrational): x is nearest to t1, checked by exact sign tests
// of the quadratic at the midpoints around x (an algebraic check independent of the library).
bool is_rounded_ray_ball_t(const double o[3], const double d[3], const double c[3], double r, double x);

// The exact minimum enclosing sphere's squared radius (CGAL Min_sphere_d over exact rationals):
// is x its nearest double? xyz holds n points as x0 y0 z0 x1 ...
bool is_rounded_min_sphere_sqradius(const double* xyz, unsigned long n, double x);
// Is every point in the closed box { c + sum si ai : |si| <= hi } (axes = a0 a1 a2, 9 values)? Exact.
bool all_in_box(const double* xyz, unsigned long n, const double c[3], const double axes[9], const double h[3]);
// Is the closed box { c + sum si ai : |si| <= hi } (axes = a0 a1 a2) inside every half-space and
// slab of s (its points, generators and plane ignored)? Its eight corners in exact rationals.
bool box_in_constraints(const double c[3], const double axes[9], const double h[3], const convex_set& s);
// Is the closed box (ic, iaxes, ih) inside the closed box (c, axes, h)? Its eight corners in exact
// rationals, each in the outer box's frame by Cramer's rule (false when the outer axes are dependent).
bool box_in_box(const double c[3], const double axes[9], const double h[3], const double ic[3], const double iaxes[9], const double ih[3]);
// Is the closed ball (center, r >= 0) inside the box (independent axes)? The centre's frame
// coordinates in exact rationals and its distance to each face, squared.
bool ball_in_box(const double c[3], const double axes[9], const double h[3], const double center[3], double r);
// Is the box inside the closed ball? Its eight corners in exact rationals.
bool box_in_ball(const double c[3], const double axes[9], const double h[3], const double center[3], double r);
// Is the box inside the closed capsule (the points within |r| of the segment ab)? Its eight corners
// in exact rationals, each one's squared distance to the segment (the nearest point of the segment
// by its clamped parameter) against r^2.
bool box_in_capsule(const double c[3], const double axes[9], const double h[3], const double a[3], const double b[3], double r);
// Is the box inside the closed tetrahedron t (its four vertices; coplanar ones are their hull)? Its
// eight corners in exact rationals: CGAL's Tetrahedron_3 side test over Epeck for a solid one; for
// a coplanar one, a corner in one of the four faces (Caratheodory), each face by rational
// barycentric signs, a collinear face as the segment between its farthest vertices.
bool box_in_tetrahedron(const double c[3], const double axes[9], const double h[3], const double t[12]);
// The closed ball against the closed axis-aligned box [mn, mx]: inside it (exact rationals), and
// meeting it (CGAL do_intersect of Sphere_3 and Iso_cuboid_3 over Epeck, a squared-distance test,
// so the ball's; an inverted box is empty).
bool ball_in_aabb(const double mn[3], const double mx[3], const double center[3], double r);
bool ball_aabb(const double mn[3], const double mx[3], const double center[3], double r);
// Is every point inside the closed ball (c, r)? Exact.
bool all_in_ball(const double* xyz, unsigned long n, const double c[3], double r);
// CGAL Min_sphere_of_spheres_d with Epick (double) for timing: returns the radius.
double min_sphere_of_spheres_epick(const double* xyz, unsigned long n);

// Bounding-volume references (cgal_hull.cpp): the convex hull's volume and area (CGAL
// convex_hull_3, Epick; 0 when flat), the hull's build time, and the volume and area of
// { x : lo_i <= d_i . x <= hi_i } (CGAL halfspace_intersection_3; `inside` strictly inside).
void hull_volume_area(const double* xyz, unsigned long n, double& volume, double& area);
// The extreme points of the set (CGAL convex_hull_3 with Epeck), sorted, as x y z triples.
std::vector<double> hull_vertices_exact(const double* xyz, unsigned long n);
// qhull's default hull (qhull_peer.cpp): time, vertex count, and whether it failed (for
// example "QH6154 initial simplex is flat" on coplanar input).
struct qhull_result {
    double ms = 0;
    unsigned long vertices = 0;
    bool error = false;
};
qhull_result qhull_hull(const double* xyz, unsigned long n);
// CGAL oriented_bounding_box (Epick, Eigen): the box's volume, and the time it took.
double obb_volume_cgal(const double* xyz, unsigned long n, double& ms);
double hull_time_ms(const double* xyz, unsigned long n, unsigned long& vertices);
void halfspaces_volume_area(const double* dirs, const double* lo, const double* hi, unsigned long m, const double inside[3], double& volume,
                            double& area);

// Epick (filtered, inexact constructions) versions for the benchmarks.
bool ray_triangle_epick(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3]);
bool ray_box_epick(const double o[3], const double d[3], const double mn[3], const double mx[3]);
bool segment_triangle_epick(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3]);
bool triangle_triangle_epick(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3],
                             const double f[3]);
bool box_box_epick(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]);
bool point_in_box_epick(const double p[3], const double mn[3], const double mx[3]);
int orient3d_epick(const double a[3], const double b[3], const double c[3], const double d[3]);
// The signed distance from point p to a capsule (segment ab, radius r; a ball when a = b) or a solid
// tetrahedron (t: its four vertices as x y z), as a CGAL Epick user computes it:
// sqrt(squared_distance(Point_3, Segment_3 | Point_3)) - |r|; outside the tetrahedron
// sqrt(squared_distance(Point_3, Tetrahedron_3)) (0 on or in it), inside minus the least
// sqrt(squared_distance(Point_3, Triangle_3)) over its faces (0 for a flat one). Rounded: double
// constructions.
double capsule_point_distance_epick(const double a[3], const double b[3], double r, const double p[3]);
double tetrahedron_point_distance_epick(const double t[12], const double p[3]);

// The exact values of intersection() (cgal_values.cpp): where a line, a ray or a segment (o and d:
// a ray's or line's origin and direction, a segment's end points) meets a set, over Epeck by other
// methods than the library's. exact_hit answers, for each quantity it has: is a double its nearest
// double (ties to even), does an interval contain it. A span's quantities: t_enter, t_exit and the
// point at t_enter (where t_enter is -infinity, at the span's parameter nearest 0); a first contact's
// (triangle, polygon, mesh): t_enter and the point; a triangle's also its barycentrics and normal.
// `declined` names why a case was not computed (an oriented box with dependent axes).
struct linear_object {
    enum kind_t { ray, segment, line } kind;
    double o[3], d[3];
};
enum class quantity : int { t_enter, t_exit, x, y, z, u, v, w, nx, ny, nz };
class exact_hit {
public:
    exact_hit();
    ~exact_hit();
    exact_hit(exact_hit&&) noexcept;
    exact_hit& operator=(exact_hit&&) noexcept;
    [[nodiscard]] bool exists() const;
    [[nodiscard]] bool has(quantity) const;
    [[nodiscard]] bool rounds_to(quantity, double x) const;
    [[nodiscard]] bool within(quantity, double lo, double hi) const;
    [[nodiscard]] double nearest(quantity) const; // approximately, for messages and bounds
    // mesh: is i a triangle at the first contact (or, for i = -1, does the object start inside)?
    [[nodiscard]] bool first_triangle_ok(std::size_t i) const;
    const char* declined = nullptr;
    struct impl;

private:
    [[nodiscard]] bool rounds_to_value(int i, double x) const;
    std::unique_ptr<impl> p;
    friend exact_hit exact_plane(const linear_object&, const double[3], double);
    friend exact_hit exact_halfspaces(const linear_object&, const std::vector<std::array<double, 4>>&);
    friend exact_hit exact_kdop(const linear_object&, const std::vector<std::array<double, 3>>&, const double*, const double*);
    friend exact_hit exact_obb(const linear_object&, const double[3], const double[9], const double[3]);
    friend exact_hit exact_tetrahedron(const linear_object&, const double[12]);
    friend exact_hit exact_ball(const linear_object&, const double[3], double);
    friend exact_hit exact_triangle(const linear_object&, const double[3], const double[3], const double[3]);
    friend exact_hit exact_polygon(const linear_object&, const polygon3_data&);
    friend exact_hit exact_mesh(const linear_object&, const mesh_data&);
};
exact_hit exact_plane(const linear_object& x, const double n[3], double c);                           // n . p = c
exact_hit exact_halfspaces(const linear_object& x, const std::vector<std::array<double, 4>>& planes); // n . p <= c each
exact_hit exact_box(const linear_object& x, const double mn[3], const double mx[3]);
exact_hit exact_kdop(const linear_object& x, const std::vector<std::array<double, 3>>& dirs, const double* mn, const double* mx);
exact_hit exact_obb(const linear_object& x, const double c[3], const double axes[9], const double h[3]);
exact_hit exact_tetrahedron(const linear_object& x, const double v[12]);
exact_hit exact_ball(const linear_object& x, const double c[3], double r);
exact_hit exact_triangle(const linear_object& x, const double a[3], const double b[3], const double c[3]);
exact_hit exact_polygon(const linear_object& x, const polygon3_data& g);
exact_hit exact_mesh(const linear_object& x, const mesh_data& m);

} // namespace oracle
