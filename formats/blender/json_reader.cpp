#include "formats/blender/json_reader.h"

#include <cstring>

namespace glint::blender {

namespace {
const char* type_name(const Json& j) {
    switch (j.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::binary: return "binary";
        case Json::value_t::discarded: return "nothing";
        default: return "a number";
    }
}
}  // namespace

void JsonReader::fail(const std::string& message) const {
    FileLoc loc;
    loc.file = file_;
    throw Error(ErrorKind::Scene, loc, (path_.empty() ? std::string("") : path_ + ": ") + message);
}

JsonReader JsonReader::at(const char* key) const {
    if (!j_->is_object()) fail(std::string("expected an object, found ") + type_name(*j_));
    auto it = j_->find(key);
    const std::string sub = path_.empty() ? key : path_ + "." + key;
    if (it == j_->end()) JsonReader(*j_, sub, file_).fail("missing");
    return JsonReader(*it, sub, file_);
}

JsonReader JsonReader::at(size_t i) const {
    if (!j_->is_array()) fail(std::string("expected an array, found ") + type_name(*j_));
    const std::string sub = path_ + "[" + std::to_string(i) + "]";
    if (i >= j_->size()) JsonReader(*j_, sub, file_).fail("missing");
    return JsonReader((*j_)[i], sub, file_);
}

double JsonReader::number() const {
    if (!j_->is_number()) fail(std::string("expected a number, found ") + type_name(*j_));
    return j_->get<double>();
}

int JsonReader::integer() const {
    if (j_->is_number_integer()) {
        const long long v = j_->get<long long>();
        if (v < -(1LL << 31) || v >= (1LL << 31)) fail("integer out of range");
        return static_cast<int>(v);
    }
    if (j_->is_number_float()) {
        const double d = j_->get<double>();
        if (d == static_cast<int>(d)) return static_cast<int>(d);
    }
    fail(std::string("expected an integer, found ") + type_name(*j_));
}

bool JsonReader::boolean() const {
    if (j_->is_boolean()) return j_->get<bool>();
    if (j_->is_number()) return j_->get<double>() != 0;
    fail(std::string("expected a boolean, found ") + type_name(*j_));
}

std::string JsonReader::string() const {
    if (!j_->is_string()) fail(std::string("expected a string, found ") + type_name(*j_));
    return j_->get<std::string>();
}

std::vector<double> JsonReader::numbers() const {
    if (!j_->is_array()) fail(std::string("expected an array of numbers, found ") + type_name(*j_));
    std::vector<double> out;
    out.reserve(j_->size());
    for (size_t i = 0; i < j_->size(); ++i) out.push_back(at(i).number());
    return out;
}

double JsonReader::number(const char* key, double fallback) const {
    return has(key) ? at(key).number() : fallback;
}
int JsonReader::integer(const char* key, int fallback) const {
    return has(key) ? at(key).integer() : fallback;
}
bool JsonReader::boolean(const char* key, bool fallback) const {
    return has(key) ? at(key).boolean() : fallback;
}
std::string JsonReader::string(const char* key, const std::string& fallback) const {
    return has(key) ? at(key).string() : fallback;
}

Vec3 JsonReader::vec3(const char* key, const Vec3& fallback) const {
    if (!has(key)) return fallback;
    const std::vector<double> v = at(key).numbers();
    if (v.size() < 3) at(key).fail("expected 3 numbers");
    return {v[0], v[1], v[2]};
}

Color JsonReader::color(const char* key, const Color& fallback) const {
    if (!has(key)) return fallback;
    const std::vector<double> v = at(key).numbers();
    if (v.size() < 3) at(key).fail("expected 3 or 4 numbers");
    return {v[0], v[1], v[2]};
}

Matrix4 JsonReader::matrix(const char* key) const { return at(key).matrix(); }

Matrix4 JsonReader::matrix() const {
    const JsonReader& m = *this;
    const std::vector<double> v = m.numbers();
    if (v.size() != 16) m.fail("expected 16 numbers (a row-major 4x4 matrix)");
    Matrix4 out;
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) {
            if (!std::isfinite(v[i * 4 + k])) m.fail("the matrix is not finite");
            out.m[i][k] = v[i * 4 + k];
        }
    return out;
}

double BufferView::get(size_t element, int component) const {
    const size_t i = element * static_cast<size_t>(components) + static_cast<size_t>(component);
    switch (type) {
        case Type::F32: {
            float f;
            std::memcpy(&f, data + i * 4, 4);
            return f;
        }
        case Type::U32:
        case Type::U16:
        case Type::U8: return index(element, component);
    }
    return 0;
}

uint32_t BufferView::index(size_t element, int component) const {
    const size_t i = element * static_cast<size_t>(components) + static_cast<size_t>(component);
    switch (type) {
        case Type::U32: {
            uint32_t v;
            std::memcpy(&v, data + i * 4, 4);
            return v;
        }
        case Type::U16: {
            uint16_t v;
            std::memcpy(&v, data + i * 2, 2);
            return v;
        }
        case Type::U8: return data[i];
        case Type::F32: return static_cast<uint32_t>(get(element, component));
    }
    return 0;
}

BufferView read_view(const JsonReader& r, const Buffers& buffers, int components,
                     std::initializer_list<BufferView::Type> types) {
    BufferView v;
    const std::string t = r.at("type").string();
    size_t size = 4;
    if (t == "f32") v.type = BufferView::Type::F32;
    else if (t == "u32") v.type = BufferView::Type::U32;
    else if (t == "u16") v.type = BufferView::Type::U16, size = 2;
    else if (t == "u8") v.type = BufferView::Type::U8, size = 1;
    else r.at("type").fail("unknown buffer type '" + t + "' (f32, u32, u16, u8)");
    bool allowed = false;
    for (BufferView::Type a : types) allowed = allowed || a == v.type;
    if (!allowed) r.at("type").fail("buffer type '" + t + "' is not allowed here");
    v.components = r.integer("components", 1);
    if (v.components != components)
        r.fail("expected " + std::to_string(components) + " component(s) per element, found " +
               std::to_string(v.components));
    const double offset = r.at("offset").number();
    const double count = r.at("count").number();
    if (!(offset >= 0) || offset != static_cast<double>(static_cast<long long>(offset)) ||
        !(count >= 0) || count != static_cast<double>(static_cast<long long>(count)))
        r.fail("offset and count must be non-negative integers");
    const auto off = static_cast<unsigned long long>(offset);
    const auto n = static_cast<unsigned long long>(count);
    const unsigned long long bytes = n * static_cast<unsigned long long>(components) * size;
    if (off % 4 != 0) r.fail("offset " + std::to_string(off) + " is not a multiple of 4");
    if (off > buffers.bytes.size() || bytes > buffers.bytes.size() - off)
        r.fail("the view (" + std::to_string(bytes) + " bytes at offset " + std::to_string(off) +
               ") lies outside " + buffers.path + " (" + std::to_string(buffers.bytes.size()) +
               " bytes)");
    v.data = buffers.bytes.data() + off;
    v.count = n;
    return v;
}

}  // namespace glint::blender
