#pragma once
/// A non-owning reference to a callable (never allocates, unlike std::function): for callbacks on hot paths.
#include <type_traits>
#include <utility>

namespace hooke {

template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
 public:
  /// Refers to `fn`, which must outlive every call.
  template <typename Fn, typename = std::enable_if_t<!std::is_same_v<std::decay_t<Fn>, FunctionRef>>>
  FunctionRef(Fn&& fn)  // NOLINT(google-explicit-constructor): passed like a lambda
      : m_object(const_cast<void*>(static_cast<const void*>(&fn))), m_call([](void* object, Args... args) -> R {
          return (*static_cast<std::add_pointer_t<Fn>>(object))(std::forward<Args>(args)...);
        }) {}
  R operator()(Args... args) const { return m_call(m_object, std::forward<Args>(args)...); }

 private:
  void* m_object;
  R (*m_call)(void*, Args...);
};

}  // namespace hooke
