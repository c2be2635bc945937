// Large-buffer allocation for the BVHs, images and line records. Buffers of at least
// kHugeThreshold bytes are aligned to 2 MiB and marked for transparent huge pages (Linux madvise),
// which cuts the number of page faults while building and TLB misses while traversing. Elsewhere,
// or below the threshold, it is ordinary aligned allocation.
#pragma once

#include <cstddef>
#include <new>
#include <utility>

namespace rays::tribvh {

constexpr size_t kHugeThreshold = size_t(4) << 20;
constexpr size_t kHugePage = size_t(2) << 20;

/// Allocates at least `bytes` (throws std::bad_alloc); free with hugeFree(p, bytes, align).
void* hugeAlloc(size_t bytes, size_t align);
void hugeFree(void* p, size_t bytes, size_t align) noexcept;
/// Marks the whole 2 MiB pages within [p, p + bytes) of a buffer allocated elsewhere for
/// transparent huge pages (nothing elsewhere than Linux).
void adviseHugePages(void* p, size_t bytes) noexcept;
/// Bytes actually reserved for a request of `bytes`.
size_t hugeFootprint(size_t bytes);

/// Allocator for std::vector: huge pages for big buffers; resize() default-initialises (no
/// zero fill) trivially constructible elements.
template <class T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
    T* allocate(size_t n) { return static_cast<T*>(hugeAlloc(n * sizeof(T), alignof(T))); }
    void deallocate(T* p, size_t n) noexcept { hugeFree(p, n * sizeof(T), alignof(T)); }
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

/// Fixed-size uninitialised array of trivially copyable T (build-time scratch).
template <class T>
class HugeArray {
public:
    HugeArray() = default;
    explicit HugeArray(size_t n)
        : data_(n ? static_cast<T*>(hugeAlloc(n * sizeof(T), alignof(T))) : nullptr), size_(n), capacity_(n) {}
    ~HugeArray() { reset(); }
    HugeArray(HugeArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)), capacity_(std::exchange(o.capacity_, 0)) {}
    HugeArray& operator=(HugeArray&& o) noexcept {
        if (this != &o) {
            reset();
            data_ = std::exchange(o.data_, nullptr);
            size_ = std::exchange(o.size_, 0);
            capacity_ = std::exchange(o.capacity_, 0);
        }
        return *this;
    }
    HugeArray(const HugeArray&) = delete;
    HugeArray& operator=(const HugeArray&) = delete;
    void reset() {
        if (data_) hugeFree(data_, capacity_ * sizeof(T), alignof(T));
        data_ = nullptr;
        size_ = capacity_ = 0;
    }
    /// Keeps the first n elements (n <= size); the storage is not shrunk.
    void truncate(size_t n) { size_ = n < size_ ? n : size_; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    size_t size() const { return size_; }
    T& operator[](size_t i) { return data_[i]; }
    const T& operator[](size_t i) const { return data_[i]; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }

private:
    T* data_ = nullptr;
    size_t size_ = 0, capacity_ = 0;
};

}  // namespace rays::tribvh
