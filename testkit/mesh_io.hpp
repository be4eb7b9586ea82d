// Triangle meshes from OFF, OBJ, PLY (ASCII and binary little-endian) and STL (ASCII and binary).
// Polygons are split into fans. Errors throw std::runtime_error naming the file and the problem.
// Formats: OFF (Princeton Shape Benchmark spec), Wavefront OBJ (v and f records), PLY (Turk 1994),
// STL (3D Systems 1989).
#pragma once
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace audit {

struct mesh {
    std::vector<incidence::point3> vertices;
    std::vector<std::array<std::uint32_t, 3>> faces;
};

namespace io_detail {
[[noreturn]] inline void fail(const std::string& file, const std::string& why) { throw std::runtime_error(file + ": " + why); }
inline void add_polygon(mesh& m, const std::vector<long>& idx, const std::string& file) {
    if (idx.size() < 3) fail(file, "a face with fewer than 3 vertices");
    for (long i : idx)
        if (i < 0 || static_cast<std::size_t>(i) >= m.vertices.size()) fail(file, "face index " + std::to_string(i) + " out of range");
    for (std::size_t k = 1; k + 1 < idx.size(); ++k)
        m.faces.push_back({std::uint32_t(idx[0]), std::uint32_t(idx[k]), std::uint32_t(idx[k + 1])});
}
inline std::string next_token(std::istream& in) { // skips '#' comments
    std::string t;
    while (in >> t) {
        if (t[0] != '#') return t;
        std::string rest;
        std::getline(in, rest);
    }
    return t;
}
inline double num(const std::string& t, const std::string& file) {
    try {
        std::size_t used = 0;
        const double v = std::stod(t, &used);
        if (used != t.size()) fail(file, "not a number: '" + t + "'");
        return v;
    } catch (const std::logic_error&) { fail(file, "not a number: '" + t + "'"); }
}

inline mesh read_off(std::istream& in, const std::string& file) {
    std::string head = next_token(in);
    if (head != "OFF") fail(file, "OFF header expected, found '" + head + "'");
    const long nv = long(num(next_token(in), file)), nf = long(num(next_token(in), file));
    (void)next_token(in); // edge count
    if (nv < 0 || nf < 0) fail(file, "negative counts");
    mesh m;
    m.vertices.reserve(std::size_t(nv));
    for (long i = 0; i < nv; ++i) {
        double p[3];
        for (double& x : p) x = num(next_token(in), file);
        m.vertices.push_back({p[0], p[1], p[2]});
        std::string rest; // optional colours on the same line
        std::getline(in, rest);
    }
    std::vector<long> idx;
    for (long f = 0; f < nf; ++f) {
        const long k = long(num(next_token(in), file));
        idx.resize(std::size_t(k < 0 ? 0 : k));
        for (long& i : idx) i = long(num(next_token(in), file));
        add_polygon(m, idx, file);
        std::string rest;
        std::getline(in, rest);
    }
    if (!in && !in.eof()) fail(file, "truncated");
    return m;
}

inline mesh read_obj(std::istream& in, const std::string& file) {
    mesh m;
    std::string line;
    std::vector<long> idx;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            double p[3];
            for (double& x : p) {
                std::string t;
                ls >> t;
                x = num(t, file);
            }
            m.vertices.push_back({p[0], p[1], p[2]});
        } else if (tag == "f") {
            idx.clear();
            std::string t;
            while (ls >> t) {
                const long i = long(num(t.substr(0, t.find('/')), file));
                idx.push_back(i < 0 ? long(m.vertices.size()) + i : i - 1);
            }
            add_polygon(m, idx, file);
        }
    }
    return m;
}

template <class T>
T load_le(const char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline mesh read_ply(std::istream& in, const std::string& file) {
    std::string line, format;
    long nv = 0, nf = 0;
    std::vector<std::string> vprops; // types of the vertex properties, in order
    std::vector<std::string> names;
    std::string list_count = "uchar", list_index = "int";
    std::string current;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ls(line);
        std::string w;
        ls >> w;
        if (w == "format") ls >> format;
        else if (w == "element") {
            ls >> current;
            long n = 0;
            ls >> n;
            if (current == "vertex") nv = n;
            else if (current == "face") nf = n;
            else if (n != 0) fail(file, "unsupported PLY element '" + current + "'");
        } else if (w == "property") {
            std::string type;
            ls >> type;
            if (current == "vertex") {
                std::string name;
                ls >> name;
                vprops.push_back(type);
                names.push_back(name);
            } else if (current == "face" && type == "list") ls >> list_count >> list_index;
        } else if (w == "end_header") break;
    }
    int ix = -1, iy = -1, iz = -1;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == "x") ix = int(i);
        if (names[i] == "y") iy = int(i);
        if (names[i] == "z") iz = int(i);
    }
    if (ix < 0 || iy < 0 || iz < 0) fail(file, "PLY vertices without x, y, z");
    mesh m;
    std::vector<long> idx;
    if (format == "ascii") {
        std::vector<double> v(vprops.size());
        for (long i = 0; i < nv; ++i) {
            for (double& x : v) x = num(next_token(in), file);
            m.vertices.push_back({v[std::size_t(ix)], v[std::size_t(iy)], v[std::size_t(iz)]});
        }
        for (long f = 0; f < nf; ++f) {
            idx.resize(std::size_t(num(next_token(in), file)));
            for (long& i : idx) i = long(num(next_token(in), file));
            add_polygon(m, idx, file);
        }
        return m;
    }
    if (format != "binary_little_endian") fail(file, "unsupported PLY format '" + format + "'");
    auto size_of = [&](const std::string& t) -> std::size_t {
        if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
        if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
        if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
        if (t == "double" || t == "float64") return 8;
        fail(file, "unsupported PLY type '" + t + "'");
    };
    auto value = [&](const std::string& t, const char* p) -> double {
        if (t == "float" || t == "float32") return load_le<float>(p);
        if (t == "double" || t == "float64") return load_le<double>(p);
        if (t == "uchar" || t == "uint8") return load_le<std::uint8_t>(p);
        if (t == "char" || t == "int8") return load_le<std::int8_t>(p);
        if (t == "ushort" || t == "uint16") return load_le<std::uint16_t>(p);
        if (t == "short" || t == "int16") return load_le<std::int16_t>(p);
        if (t == "uint" || t == "uint32") return load_le<std::uint32_t>(p);
        return load_le<std::int32_t>(p);
    };
    std::size_t stride = 0;
    std::vector<std::size_t> at;
    for (const auto& t : vprops) at.push_back(stride), stride += size_of(t);
    std::vector<char> buf(stride);
    for (long i = 0; i < nv; ++i) {
        if (!in.read(buf.data(), std::streamsize(stride))) fail(file, "truncated vertex data");
        auto get = [&](int k) { return value(vprops[std::size_t(k)], buf.data() + at[std::size_t(k)]); };
        m.vertices.push_back({get(ix), get(iy), get(iz)});
    }
    const std::size_t cs = size_of(list_count), is = size_of(list_index);
    char tmp[8];
    for (long f = 0; f < nf; ++f) {
        if (!in.read(tmp, std::streamsize(cs))) fail(file, "truncated face data");
        idx.resize(std::size_t(value(list_count, tmp)));
        for (long& i : idx) {
            if (!in.read(tmp, std::streamsize(is))) fail(file, "truncated face data");
            i = long(value(list_index, tmp));
        }
        add_polygon(m, idx, file);
    }
    return m;
}

// STL stores triangles with repeated corners: weld exact duplicates into shared vertices.
inline mesh read_stl(std::istream& in, const std::string& file, bool ascii) {
    mesh m;
    std::map<std::tuple<double, double, double>, std::uint32_t> index;
    auto vertex = [&](double x, double y, double z) {
        auto [it, fresh] = index.try_emplace({x, y, z}, std::uint32_t(m.vertices.size()));
        if (fresh) m.vertices.push_back({x, y, z});
        return long(it->second);
    };
    std::vector<long> idx;
    if (ascii) {
        std::string t;
        while (in >> t) {
            if (t != "vertex") continue;
            double p[3];
            for (double& x : p) x = num(next_token(in), file);
            idx.push_back(vertex(p[0], p[1], p[2]));
            if (idx.size() == 3) add_polygon(m, idx, file), idx.clear();
        }
        return m;
    }
    char header[84];
    if (!in.read(header, 84)) fail(file, "truncated STL header");
    const std::uint32_t n = load_le<std::uint32_t>(header + 80);
    char rec[50];
    for (std::uint32_t f = 0; f < n; ++f) {
        if (!in.read(rec, 50)) fail(file, "truncated STL triangle " + std::to_string(f));
        idx.clear();
        for (int k = 0; k < 3; ++k)
            idx.push_back(vertex(load_le<float>(rec + 12 + 12 * k), load_le<float>(rec + 16 + 12 * k), load_le<float>(rec + 20 + 12 * k)));
        add_polygon(m, idx, file);
    }
    return m;
}
} // namespace io_detail

inline mesh read_mesh(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) io_detail::fail(file, "cannot open");
    auto ext = file.substr(file.find_last_of('.') + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    mesh m;
    if (ext == "off") m = io_detail::read_off(in, file);
    else if (ext == "obj") m = io_detail::read_obj(in, file);
    else if (ext == "ply") m = io_detail::read_ply(in, file);
    else if (ext == "stl") {
        char head[6] = {};
        in.read(head, 5);
        // "solid" also starts some binary headers: ASCII only if the size does not match binary.
        in.clear();
        in.seekg(0, std::ios::end);
        const auto size = static_cast<long long>(in.tellg());
        char count[4] = {};
        in.seekg(80);
        in.read(count, 4);
        in.clear();
        in.seekg(0);
        const bool ascii = std::string(head) == "solid" && size != 84 + 50LL * io_detail::load_le<std::uint32_t>(count);
        m = io_detail::read_stl(in, file, ascii);
    } else io_detail::fail(file, "unknown mesh format '." + ext + "' (OFF, OBJ, PLY or STL)");
    if (m.faces.empty()) io_detail::fail(file, "no faces");
    for (const auto& p : m.vertices)
        if (!incidence::is_finite(p)) io_detail::fail(file, "a vertex with a NaN or infinite coordinate");
    return m;
}

} // namespace audit
