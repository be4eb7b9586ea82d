// A minimal JSON writer for the audit (objects, arrays, strings, numbers, booleans).
#pragma once
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace audit {

class json {
public:
    json& open(char c) {
        value_prefix();
        out_ += c;
        first_.push_back(true);
        return *this;
    }
    json& close(char c) {
        out_ += c;
        first_.pop_back();
        return *this;
    }
    json& object() { return open('{'); }
    json& end_object() { return close('}'); }
    json& array() { return open('['); }
    json& end_array() { return close(']'); }
    json& key(const std::string& k) {
        comma();
        quote(k);
        out_ += ':';
        after_key_ = true;
        return *this;
    }
    json& str(const std::string& s) {
        value_prefix();
        quote(s);
        return *this;
    }
    json& num(double v) {
        value_prefix();
        if (!std::isfinite(v)) {
            out_ += "null";
            return *this;
        }
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        out_ += buf;
        return *this;
    }
    json& num(long v) {
        value_prefix();
        out_ += std::to_string(v);
        return *this;
    }
    json& num(int v) { return num(long(v)); }
    json& num(unsigned v) { return num(long(v)); }
    json& num(std::size_t v) { return num(long(v)); }
    json& boolean(bool b) {
        value_prefix();
        out_ += b ? "true" : "false";
        return *this;
    }
    json& null() {
        value_prefix();
        out_ += "null";
        return *this;
    }
    // key/value shorthands
    json& kv(const std::string& k, const std::string& v) { return key(k).str(v); }
    json& kv(const std::string& k, const char* v) { return key(k).str(v); }
    json& kv(const std::string& k, double v) { return key(k).num(v); }
    json& kv(const std::string& k, long v) { return key(k).num(v); }
    json& kv(const std::string& k, int v) { return key(k).num(v); }
    json& kv(const std::string& k, std::size_t v) { return key(k).num(v); }
    json& kv(const std::string& k, bool v) { return key(k).boolean(v); }
    template <class T>
    json& list(const std::string& k, const std::vector<T>& v) {
        key(k).array();
        for (const T& x : v) num(x);
        return end_array();
    }
    [[nodiscard]] const std::string& text() const { return out_; }

private:
    void comma() {
        if (!first_.empty()) {
            if (!first_.back()) out_ += ',';
            first_.back() = false;
        }
    }
    void value_prefix() {
        if (after_key_) after_key_ = false;
        else comma();
    }
    void quote(const std::string& s) {
        out_ += '"';
        for (const char ch : s) {
            const auto c = static_cast<unsigned char>(ch);
            if (c == '"' || c == '\\') out_ += '\\', out_ += ch;
            else if (c == '\n') out_ += "\\n";
            else if (c < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out_ += buf;
            } else out_ += ch;
        }
        out_ += '"';
    }
    std::string out_;
    std::vector<bool> first_;
    bool after_key_ = false;
};

} // namespace audit
