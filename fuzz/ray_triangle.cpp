// ray3 x triangle3 (and segment3 x triangle3, triangle3 x triangle3 and aabb3 x triangle3 on the
// same bytes, and plane3 x segment3 and plane3 x triangle3: the second triangle is the ray's two points and doubles 15..17, the box's corners
// are doubles 0..5): differential against CGAL
// Epeck for the exact tier; conservative never misses, aggressive never lies, classify is never
// wrong; both argument orders agree; every tier and intersection() survive raw bit patterns
// (NaN, infinities, subnormals, zero directions, degenerate triangles). And the batch: the ray
// against nine triangles from the same bytes (t, u, t's vertices permuted, t's edges with other
// apexes, doubles 18..31), and six rays of the same bytes against t, on a SIMD target the first
// (second) byte picks, every lane equal to the scalar answer in every tier; the ray's first hit
// among the nine (batch::intersection) is the scene's over them; the nine and the ray rounded to
// float as a float packet (batch::triangles_soa_f), the filtered tiers' lanes the scalar answers.
// Any finding aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>
import incidence;
#include "contracts.hpp"
#include "batches.hpp"

using namespace incidence;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[32] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const ray3 r{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    const segment3 s{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    const triangle3 t{{v[6], v[7], v[8]}, {v[9], v[10], v[11]}, {v[12], v[13], v[14]}};
    const triangle3 u{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[15], v[16], v[17]}};
    const auto ts = nine_triangles(v);
    batch_contracts(r, std::span<const triangle3>(ts), size > 0 ? data[0] : 0);
    // many rays against one triangle: the ray, its reverse, rays from the other doubles, one from a vertex of t
    const ray3 rays[6] = {r,
                          {r.origin, vec3{-v[3], -v[4], -v[5]}},
                          {{v[18], v[19], v[20]}, {v[21], v[22], v[23]}},
                          {{v[24], v[25], v[26]}, t.a - point3{v[24], v[25], v[26]}},
                          {t.b, {v[27], v[28], v[29]}},
                          {{v[30], v[31], v[0]}, t.c - point3{v[30], v[31], v[0]}}};
    batch_contracts(t, std::span<const ray3>(rays), size > 1 ? data[1] : 0);
    // the nine rounded to floats (a float packet) and the ray too: the filtered tiers' lanes are the
    // scalar answers on the widened triangles; the float approximate tier answers 0 or 1 and counts them
    {
        auto to_float = [](double x) { // no double outside float's range is converted
            if (x > 0x1.fffffep127) return __builtin_huge_valf();
            if (x < -0x1.fffffep127) return -__builtin_huge_valf();
            return static_cast<float>(x);
        };
        std::vector<float> c[9];
        for (const triangle3& x : ts) {
            const double w[9] = {x.a.x, x.a.y, x.a.z, x.b.x, x.b.y, x.b.z, x.c.x, x.c.y, x.c.z};
            for (int k = 0; k < 9; ++k) c[k].push_back(to_float(w[k]));
        }
        const batch::triangles_soa_f packet{c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]};
        const ray3 fr{{to_float(v[0]), to_float(v[1]), to_float(v[2])}, {to_float(v[3]), to_float(v[4]), to_float(v[5])}};
        std::uint8_t out[9];
        auto same = [&](auto tier, const ray3& ray) {
            using Tier = decltype(tier);
            const auto met = batch::intersects<Tier>(ray, packet, out);
            if (!met) std::abort();
            std::size_t count = 0;
            for (std::size_t i = 0; i < 9; ++i) {
                if (out[i] > 1) std::abort();
                if constexpr (!std::is_same_v<Tier, approximate>)
                    if ((out[i] == 1) != intersects<Tier>(ray, packet[i])) std::abort();
                count += out[i];
            }
            if (met.value() != count) std::abort();
        };
        for (const ray3& ray : {fr, r}) {
            same(exact{}, ray);
            same(conservative{}, ray);
            same(aggressive{}, ray);
            same(approximate{}, ray);
        }
    }
    // the first hit among the nine: the scene's over the same triangles (exact, conservative,
    // aggressive: value for value; without a scene, non-finite input: an exact hit is a triangle met)
    {
        const auto first = batch::intersection<exact>(r, std::span<const triangle3>(ts));
        if (!first) std::abort();
        const auto& h = first.value();
        if (const auto scene = scene3::make(std::span<const triangle3>(ts))) {
            const auto truth = intersection<exact>(r, scene.value());
            if (h.has_value() != truth.has_value()) std::abort();
            if (h && (h->triangle != truth->triangle || h->t != truth->t || h->u != truth->u || h->v != truth->v)) std::abort();
            const auto c = batch::intersection<conservative>(r, std::span<const triangle3>(ts));
            const auto ct = intersection<conservative>(r, scene.value());
            if (!c || c.value().has_value() != ct.has_value() || (ct && c.value()->triangle != ct->triangle)) std::abort();
            const auto a = batch::intersection<aggressive>(r, std::span<const triangle3>(ts));
            const auto at = intersection<aggressive>(r, scene.value());
            if (!a || a.value().has_value() != at.has_value() || (at && a.value()->triangle != at->triangle)) std::abort();
        } else if (h && !intersects<exact>(r, ts[h->triangle])) {
            std::abort();
        }
        (void)batch::intersection<approximate>(r, std::span<const triangle3>(ts));
    }
    // Every tier and every find must finish on any bits.
    (void)intersects<approximate>(r, t);
    (void)intersects<conservative>(r, t);
    (void)intersects<aggressive>(r, t);
    (void)method::ray_triangle_moller_trumbore(r, t);
    const auto h = intersection(r, t);
    (void)intersection<approximate>(r, t);
    (void)intersection(s, t);
    (void)intersects<approximate>(u, t);
    (void)intersects<conservative>(u, t);
    (void)intersects<aggressive>(t, u);
    (void)method::triangle_triangle_sat(u, t);
    const aabb3 box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    (void)intersects<approximate>(box, t);
    (void)intersects<conservative>(t, box);
    (void)intersects<aggressive>(box, t);
    const bool box_hit = intersects<exact>(box, t);
    const plane3 pl{{v[3], v[4], v[5]}, v[15]}; // plane_segment, plane_triangle: normal 3..5, offset 15
    const segment3 ps{{v[0], v[1], v[2]}, {v[16], v[17], v[15]}};
    (void)intersects<approximate>(pl, t);
    (void)intersects<conservative>(ps, pl);
    (void)intersects<aggressive>(t, pl);
    bool finite = true; // the ray, segment and t: doubles 0..14
    for (int i = 0; i < 15; ++i) finite = finite && std::isfinite(v[i]);
    const bool u_all_finite = finite && std::isfinite(v[15]) && std::isfinite(v[16]) && std::isfinite(v[17]);
    if (!u_all_finite && intersects<exact>(u, t)) std::abort(); // the exact tier says no for NaN/inf input
    if (!finite) {
        if (intersects<exact>(r, t) || h || box_hit) std::abort();
        return 0;
    }
    if (oracle::triangle_is_degenerate(v + 6, v + 9, v + 12)) {
        (void)intersects<exact>(r, t);
        (void)intersects<exact>(u, t);
        return 0; // CGAL's do_intersect requires a non-degenerate triangle
    }
    if (u_all_finite) {
        if (!oracle::triangle_is_degenerate(v, v + 3, v + 15))
            contracts(u, t, oracle::triangle_triangle(v, v + 3, v + 15, v + 6, v + 9, v + 12));
        else (void)intersects<exact>(u, t);
    }
    if (u_all_finite && !(v[3] == 0 && v[4] == 0 && v[5] == 0)) {
        double n[3] = {v[3], v[4], v[5]}, q[3] = {v[16], v[17], v[15]};
        contracts(pl, ps, oracle::plane_segment(n, v[15], v, q));
        contracts(pl, t, oracle::plane_triangle(n, v[15], v + 6, v + 9, v + 12));
    }
    if (v[0] <= v[3] && v[1] <= v[4] && v[2] <= v[5]) contracts(box, t, oracle::box_triangle(v, v + 3, v + 6, v + 9, v + 12));
    else if (box_hit) std::abort(); // an inverted box is empty
    if (!(v[3] == 0 && v[4] == 0 && v[5] == 0)) contracts(r, t, oracle::ray_triangle(v, v + 3, v + 6, v + 9, v + 12));
    if (!(v[0] == v[3] && v[1] == v[4] && v[2] == v[5])) contracts(s, t, oracle::segment_triangle(v, v + 3, v + 6, v + 9, v + 12));
    return 0;
}
