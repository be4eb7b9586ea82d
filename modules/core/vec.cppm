// Points and vectors are distinct types: point - point -> vec, point + vec -> point,
// and point + point does not compile (tests/static/vec.cpp proves it).
export module incidence.core:vec;

export namespace incidence {

struct vec2 {
    double x, y;
    friend constexpr bool operator==(const vec2&, const vec2&) = default;
};
struct point2 {
    double x, y;
    friend constexpr bool operator==(const point2&, const point2&) = default;
};
struct vec3 {
    double x, y, z;
    friend constexpr bool operator==(const vec3&, const vec3&) = default;
};
struct point3 {
    double x, y, z;
    friend constexpr bool operator==(const point3&, const point3&) = default;
};

[[nodiscard]] constexpr vec2 operator-(point2 a, point2 b) { return {a.x - b.x, a.y - b.y}; }
[[nodiscard]] constexpr point2 operator+(point2 a, vec2 v) { return {a.x + v.x, a.y + v.y}; }
[[nodiscard]] constexpr point2 operator-(point2 a, vec2 v) { return {a.x - v.x, a.y - v.y}; }
[[nodiscard]] constexpr vec2 operator+(vec2 a, vec2 b) { return {a.x + b.x, a.y + b.y}; }
[[nodiscard]] constexpr vec2 operator-(vec2 a, vec2 b) { return {a.x - b.x, a.y - b.y}; }
[[nodiscard]] constexpr vec2 operator-(vec2 a) { return {-a.x, -a.y}; }
[[nodiscard]] constexpr vec2 operator*(double s, vec2 a) { return {s * a.x, s * a.y}; }
[[nodiscard]] constexpr double dot(vec2 a, vec2 b) { return a.x * b.x + a.y * b.y; }
[[nodiscard]] constexpr double cross(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

[[nodiscard]] constexpr vec3 operator-(point3 a, point3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[nodiscard]] constexpr point3 operator+(point3 a, vec3 v) { return {a.x + v.x, a.y + v.y, a.z + v.z}; }
[[nodiscard]] constexpr point3 operator-(point3 a, vec3 v) { return {a.x - v.x, a.y - v.y, a.z - v.z}; }
[[nodiscard]] constexpr vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
[[nodiscard]] constexpr vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[nodiscard]] constexpr vec3 operator-(vec3 a) { return {-a.x, -a.y, -a.z}; }
[[nodiscard]] constexpr vec3 operator*(double s, vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
[[nodiscard]] constexpr vec3 operator*(vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
[[nodiscard]] constexpr double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[nodiscard]] constexpr vec3 cross(vec3 a, vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
[[nodiscard]] constexpr double squared_length(vec3 a) { return dot(a, a); }

// Finite means neither NaN nor infinite; constexpr (std::isfinite is not, in C++20).
[[nodiscard]] constexpr bool is_finite(double v) { return v - v == 0.0; }
[[nodiscard]] constexpr bool is_finite(vec3 v) { return is_finite(v.x) && is_finite(v.y) && is_finite(v.z); }
[[nodiscard]] constexpr bool is_finite(point3 p) { return is_finite(p.x) && is_finite(p.y) && is_finite(p.z); }
[[nodiscard]] constexpr bool is_finite(vec2 v) { return is_finite(v.x) && is_finite(v.y); }
[[nodiscard]] constexpr bool is_finite(point2 p) { return is_finite(p.x) && is_finite(p.y); }

} // namespace incidence
