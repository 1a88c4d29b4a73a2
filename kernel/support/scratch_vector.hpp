// Working memory that a resize leaves unwritten. A std::vector zeroes every
// element it adds, and for a scene's arrays of millions of entries that pass
// is also where the OS maps and clears each new page, on the calling thread
// alone. Here the new elements are left as they are, so each page is first
// touched by the thread whose share writes it, and nothing is written twice.
// Only for element types with nothing to construct; every element must be
// written before it is read. Internal to the library.
#pragma once

#include <obbsat/rect_records.hpp>

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace obbsat::detail {

/// An allocator that default-initializes what it constructs without
/// arguments (no write for a trivial type) and forwards everything else to
/// `Base`.
template <class T, class Base = std::allocator<T>>
struct unwritten_allocator : Base {
    static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>,
                  "unwritten memory is for element types with nothing to construct");
    using value_type = T;
    template <class U>
    struct rebind {
        using other = unwritten_allocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
    };

    unwritten_allocator() = default;
    template <class U, class B>
    unwritten_allocator(const unwritten_allocator<U, B>& other) noexcept : Base(static_cast<const B&>(other)) {}

    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
    }
};

/// A vector of working memory (see the top of this file).
template <class T>
using scratch_vector = std::vector<T, unwritten_allocator<T>>;

/// A vector of working memory in record memory: 64-byte aligned, huge pages
/// for large blocks (see allocate_record_memory).
template <class T>
using scratch_records = std::vector<T, unwritten_allocator<T, cache_line_allocator<T>>>;

}  // namespace obbsat::detail
