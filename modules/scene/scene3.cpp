// scene3: the hierarchy's construction (see scene3.cppm for the method and its source).
module;
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
module incidence.scene;
import incidence.core;
import incidence.shapes;

namespace incidence {

namespace {

constexpr int bins = 16;
constexpr std::uint32_t leaf_min = 2, leaf_max = 8;

struct item {
    aabb3 box;
    double centroid[3];
    std::uint32_t index;
};

aabb3 box_of(const triangle3& t) {
    auto lo = [](double a, double b, double c) { return std::min(a, std::min(b, c)); };
    auto hi = [](double a, double b, double c) { return std::max(a, std::max(b, c)); };
    return {{lo(t.a.x, t.b.x, t.c.x), lo(t.a.y, t.b.y, t.c.y), lo(t.a.z, t.b.z, t.c.z)},
            {hi(t.a.x, t.b.x, t.c.x), hi(t.a.y, t.b.y, t.c.y), hi(t.a.z, t.b.z, t.c.z)}};
}
aabb3 joined(const aabb3& a, const aabb3& b) {
    return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y), std::min(a.min.z, b.min.z)},
            {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y), std::max(a.max.z, b.max.z)}};
}
double lo_of(const aabb3& b, int axis) { return axis == 0 ? b.min.x : (axis == 1 ? b.min.y : b.min.z); }
double hi_of(const aabb3& b, int axis) { return axis == 0 ? b.max.x : (axis == 1 ? b.max.y : b.max.z); }

// Half a length, halved first so that nothing overflows near the largest doubles.
double half_side(const aabb3& b, int axis) { return hi_of(b, axis) / 2 - lo_of(b, axis) / 2; }
// Half the surface area of a box, its sides divided by `unit` (so that no product overflows).
double half_area(const aabb3& b, double unit) {
    const double x = half_side(b, 0) / unit, y = half_side(b, 1) / unit, z = half_side(b, 2) / unit;
    return x * y + y * z + z * x;
}

// A split of a node's items by the bin of their centroid along one axis.
struct split {
    int axis = -1;
    double low = 0.0, extent = 0.0; // the centroids' least coordinate and half their range on the axis
    int last_bin = 0;               // the bins up to this one go first
    double cost = 0.0;
    [[nodiscard]] int bin_of(const item& it) const {
        const int b = static_cast<int>((it.centroid[axis] / 2 - low / 2) / extent * bins);
        return std::clamp(b, 0, bins - 1);
    }
};

// The cheapest binned split of a node's items (cost relative to one triangle test per triangle).
split best_split(std::span<const item> items, const aabb3& bounds) {
    double cmin[3] = {__builtin_huge_val(), __builtin_huge_val(), __builtin_huge_val()};
    double cmax[3] = {-__builtin_huge_val(), -__builtin_huge_val(), -__builtin_huge_val()};
    for (const item& it : items)
        for (int a = 0; a < 3; ++a) cmin[a] = std::min(cmin[a], it.centroid[a]), cmax[a] = std::max(cmax[a], it.centroid[a]);
    const double unit = std::max({half_side(bounds, 0), half_side(bounds, 1), half_side(bounds, 2), 0x1p-1022});
    const double parent = half_area(bounds, unit);
    split best;
    for (int a = 0; a < 3; ++a) {
        split trial{a, cmin[a], cmax[a] / 2 - cmin[a] / 2};
        if (!(trial.extent > 0.0)) continue;
        aabb3 box[bins];
        std::uint32_t count[bins] = {};
        for (const item& it : items) {
            const int b = trial.bin_of(it);
            box[b] = count[b] == 0 ? it.box : joined(box[b], it.box);
            ++count[b];
        }
        // Sweep: the areas and counts to the right of each plane, then from the left.
        double right_area[bins];
        std::uint32_t right_count[bins];
        aabb3 acc{};
        std::uint32_t n = 0;
        for (int b = bins - 1; b > 0; --b) {
            if (count[b] != 0) acc = n == 0 ? box[b] : joined(acc, box[b]), n += count[b];
            right_area[b] = n == 0 ? 0.0 : half_area(acc, unit);
            right_count[b] = n;
        }
        acc = aabb3{};
        n = 0;
        for (int b = 0; b + 1 < bins; ++b) {
            if (count[b] != 0) acc = n == 0 ? box[b] : joined(acc, box[b]), n += count[b];
            if (n == 0 || right_count[b + 1] == 0) continue;
            const double cost = 1.0 + (half_area(acc, unit) * n + right_area[b + 1] * right_count[b + 1]) / parent;
            if (best.axis < 0 || cost < best.cost) best = {a, trial.low, trial.extent, b, cost};
        }
    }
    return best;
}

struct builder {
    std::vector<item> items;
    std::vector<scene3::node>& nodes;

    aabb3 bounds_of(std::size_t first, std::size_t last) const {
        aabb3 b = items[first].box;
        for (std::size_t i = first + 1; i < last; ++i) b = joined(b, items[i].box);
        return b;
    }
    // Builds the node at `at` over items[first, last), then its children.
    void build(std::size_t at, std::size_t first, std::size_t last, int depth) {
        const aabb3 box = bounds_of(first, last);
        const auto count = static_cast<std::uint32_t>(last - first);
        nodes[at] = {box, static_cast<std::uint32_t>(first), count, 0};
        if (count <= leaf_min || depth >= scene3::max_depth) return;
        const split s = best_split(std::span<const item>(items).subspan(first, last - first), box);
        std::size_t mid = first;
        int axis = s.axis;
        if (s.axis >= 0 && (s.cost < double(count) || count > leaf_max)) {
            mid = static_cast<std::size_t>(std::partition(items.begin() + static_cast<std::ptrdiff_t>(first),
                                                          items.begin() + static_cast<std::ptrdiff_t>(last),
                                                          [&](const item& it) { return s.bin_of(it) <= s.last_bin; }) -
                                           items.begin());
        } else if (count > leaf_max) { // every centroid in one place: halves in the given order
            mid = first + count / 2;
            axis = 0;
        }
        if (mid == first || mid == last) return; // a leaf
        const auto child = static_cast<std::uint32_t>(nodes.size());
        nodes.push_back({});
        nodes.push_back({});
        nodes[at] = {box, child, 0, static_cast<std::uint32_t>(axis)};
        build(child, first, mid, depth + 1);
        build(child + 1, mid, last, depth + 1);
    }
};

} // namespace

result<scene3> scene3::make(std::span<const triangle3> triangles) {
    if (triangles.size() >= 0xffffffffu) return error{errc::too_large};
    scene3 s;
    constexpr double moderate_limit = 0x1p400;
    std::vector<item> items;
    items.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const triangle3& t = triangles[i];
        if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c)) return error{errc::not_finite};
        const aabb3 b = box_of(t);
        for (int a = 0; a < 3; ++a)
            if (!(std::fabs(lo_of(b, a)) <= moderate_limit && std::fabs(hi_of(b, a)) <= moderate_limit)) s.moderate_ = false;
        // the centroid of the box, halved first so that it cannot overflow
        items.push_back(
            {b, {b.min.x / 2 + b.max.x / 2, b.min.y / 2 + b.max.y / 2, b.min.z / 2 + b.max.z / 2}, static_cast<std::uint32_t>(i)});
    }
    if (items.empty()) return s;
    s.nodes_.reserve(2 * items.size());
    s.nodes_.push_back({});
    builder b{std::move(items), s.nodes_};
    b.build(0, 0, b.items.size(), 0);
    s.triangles_.reserve(b.items.size());
    s.source_.reserve(b.items.size());
    for (const item& it : b.items) {
        s.triangles_.push_back(triangles[it.index]);
        s.source_.push_back(it.index);
    }
    s.nodes_.shrink_to_fit();
    return s;
}

result<scene3> scene3::make(std::span<const point3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles) {
    std::vector<triangle3> t;
    t.reserve(triangles.size());
    for (const auto& f : triangles) {
        if (f[0] >= vertices.size() || f[1] >= vertices.size() || f[2] >= vertices.size()) return error{errc::index_out_of_range};
        t.push_back({vertices[f[0]], vertices[f[1]], vertices[f[2]]});
    }
    return make(t);
}

} // namespace incidence
