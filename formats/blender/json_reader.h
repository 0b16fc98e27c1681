// Reading the exchange's JSON with messages that name where a value is: `file: meshes[3].
// positions: expected a buffer view`. A thin layer over nlohmann-json.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/transform.h"

namespace glint::blender {

using Json = nlohmann::json;

// The binary buffer file, read whole.
struct Buffers {
    std::string path;
    std::vector<unsigned char> bytes;
};

class JsonReader {
public:
    JsonReader(const Json& j, std::string path, std::shared_ptr<const std::string> file)
        : j_(&j), path_(std::move(path)), file_(std::move(file)) {}

    const Json& json() const { return *j_; }
    const std::string& path() const { return path_; }
    bool has(const char* key) const { return j_->is_object() && j_->contains(key); }
    JsonReader at(const char* key) const;  // required member
    JsonReader at(size_t i) const;         // array element
    size_t size() const { return j_->is_array() ? j_->size() : 0; }
    bool is_array() const { return j_->is_array(); }
    bool is_null() const { return j_->is_null(); }

    double number() const;
    int integer() const;
    bool boolean() const;
    std::string string() const;
    std::vector<double> numbers() const;  // an array of numbers

    double number(const char* key, double fallback) const;
    int integer(const char* key, int fallback) const;
    bool boolean(const char* key, bool fallback) const;
    std::string string(const char* key, const std::string& fallback) const;
    Vec3 vec3(const char* key, const Vec3& fallback) const;
    Color color(const char* key, const Color& fallback) const;
    Matrix4 matrix(const char* key) const;  // 16 numbers, row-major
    Matrix4 matrix() const;                 // this value as one

    [[noreturn]] void fail(const std::string& message) const;

private:
    const Json* j_;
    std::string path_;
    std::shared_ptr<const std::string> file_;
};

// A buffer view (FORMAT.md) checked against the buffer file: `count` elements of
// `components` values of one type.
struct BufferView {
    const unsigned char* data = nullptr;
    size_t count = 0;
    int components = 1;
    enum class Type { F32, U32, U16, U8 } type = Type::F32;
    double get(size_t element, int component) const;
    uint32_t index(size_t element, int component = 0) const;  // integer types
};

// Reads a view; `components` and the allowed types checked (fails naming the JSON path).
BufferView read_view(const JsonReader& r, const Buffers& buffers, int components,
                     std::initializer_list<BufferView::Type> types);

}  // namespace glint::blender
