#pragma once

#include <memory>
#include <type_traits>
#include <vector>

namespace sylva {

/// An allocator whose value-less construct() default-initializes instead of
/// value-initializing: resize() of a vector of trivial elements then leaves the new elements
/// uninitialized instead of zeroing them, for buffers whose new slots are all written next
/// (zeroing 58k metamers of new shoots before writing them cost ~0.5 ms a growth cycle).
template <class T, class Base = std::allocator<T>> class DefaultInitAllocator : public Base {
    using Traits = std::allocator_traits<Base>;

public:
    template <class U> struct rebind {
        using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
    };
    using Base::Base;
    DefaultInitAllocator() = default;
    template <class U, class B>
    DefaultInitAllocator(const DefaultInitAllocator<U, B>& other) noexcept
        : Base(static_cast<const B&>(other)) {}

    template <class U> void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args> void construct(U* p, Args&&... args) {
        Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
    }
};

/// A std::vector whose resize() does not zero trivial elements (see DefaultInitAllocator).
/// Everything else, including resize(n, value) and push_back, behaves as in std::vector.
template <class T> using RawVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace sylva
