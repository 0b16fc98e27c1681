// A list of at most N values stored in place, whose unused slots are never built or copied.
// The path tracer makes a closure list and a closure set at every vertex, with room for 16
// closures each (a few hundred bytes apiece) where most surfaces fill one: as plain arrays,
// building and copying the unused slots took a tenth of a Blender scene's render time.
#pragma once

#include <cassert>
#include <cstring>
#include <new>
#include <type_traits>

namespace glint {

template <class T, int N>
class FixedList {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "FixedList copies its values as bytes and never destroys them");

public:
    static constexpr int kCapacity = N;

    FixedList() {}
    FixedList(const FixedList& o) : size_(o.size_) { copy_from(o); }
    FixedList& operator=(const FixedList& o) {
        if (this != &o) {
            size_ = o.size_;
            copy_from(o);
        }
        return *this;
    }

    int size() const { return size_; }
    bool empty() const { return size_ == 0; }
    bool full() const { return size_ >= N; }
    void clear() { size_ = 0; }

    T& operator[](int i) {
        assert(i >= 0 && i < size_);
        return data()[i];
    }
    const T& operator[](int i) const {
        assert(i >= 0 && i < size_);
        return data()[i];
    }
    T* begin() { return data(); }
    T* end() { return data() + size_; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size_; }
    T& back() { return (*this)[size_ - 1]; }

    // False (and nothing added) when the list is full.
    bool push_back(const T& v) {
        if (full()) return false;
        new (slot(size_++)) T(v);
        return true;
    }
    // A default-built value at the end; the list must not be full.
    T& emplace_back() {
        assert(!full());
        return *new (slot(size_++)) T();
    }
    void pop_back() {
        assert(size_ > 0);
        --size_;
    }

private:
    void* slot(int i) { return bytes_ + static_cast<size_t>(i) * sizeof(T); }
    // (Values are placed by new into the bytes; trivially copyable, they are read in place.)
    T* data() { return reinterpret_cast<T*>(bytes_); }
    const T* data() const { return reinterpret_cast<const T*>(bytes_); }
    void copy_from(const FixedList& o) {
        if (size_ > 0) std::memcpy(bytes_, o.bytes_, static_cast<size_t>(size_) * sizeof(T));
    }

    int size_ = 0;
    alignas(T) unsigned char bytes_[static_cast<size_t>(N) * sizeof(T)];
};

}  // namespace glint
