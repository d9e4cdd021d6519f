// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Owning pointers with a copy that a class can rely on, so that a class holding them (World)
// is copied by = default and no member is forgotten in a hand-written copy.

#include <memory>
#include <utility>

namespace rigidlab::physics {

/// Owns a polymorphic T and copies it by T::clone(): the copy carries the original's state.
template <typename T> class ClonePtr {
public:
    ClonePtr() = default;
    explicit ClonePtr(std::unique_ptr<T> p) : m_p(std::move(p)) {}
    ClonePtr(const ClonePtr& o) : m_p(o.m_p ? o.m_p->clone() : nullptr) {}
    ClonePtr& operator=(const ClonePtr& o)
    {
        if (this != &o)
            m_p = o.m_p ? o.m_p->clone() : nullptr;
        return *this;
    }
    ClonePtr(ClonePtr&&) noexcept = default;
    ClonePtr& operator=(ClonePtr&&) noexcept = default;
    ~ClonePtr() = default;

    T& operator*() const { return *m_p; }
    T* operator->() const { return m_p.get(); }
    explicit operator bool() const { return m_p != nullptr; }

private:
    std::unique_ptr<T> m_p;
};

/// Owns a T of reusable buffers that hold no state: a copy, or a copy assignment, starts with
/// a fresh, empty T. T may be incomplete where this is declared; it must be complete where
/// the owner's constructors, destructor and assignments are defined.
template <typename T> class FreshOnCopy {
public:
    FreshOnCopy() : m_p(std::make_unique<T>()) {}
    FreshOnCopy(const FreshOnCopy&) : m_p(std::make_unique<T>()) {}
    FreshOnCopy& operator=(const FreshOnCopy& o)
    {
        if (this != &o)
            m_p = std::make_unique<T>();
        return *this;
    }
    FreshOnCopy(FreshOnCopy&&) noexcept = default;
    FreshOnCopy& operator=(FreshOnCopy&&) noexcept = default;
    ~FreshOnCopy() = default;

    T& operator*() const { return *m_p; }
    T* operator->() const { return m_p.get(); }

private:
    std::unique_ptr<T> m_p;
};

} // namespace rigidlab::physics
