#pragma once
// MemoryBytes: what a container holds on the heap, counted from its sizes (deterministic: the same run gives the
// same counts on every machine, unlike the allocator's statistics). Used by the smoothers' memoryBytes(), which
// the hybrid belief's memory bound reads (hybrid/HybridOptions.h, maxMemoryMiB).
//
// Counts are of the elements a container has room for (capacity), plus a fixed per-node overhead for node-based
// containers (kNodeOverhead: the links of a red-black-tree or hash node and the allocator's header, 48 bytes on
// the 64-bit ABIs we build for). Heap blocks the elements own themselves are added by the caller.

#include <cstddef>
#include <map>
#include <unordered_map>
#include <vector>

namespace semslam {

inline constexpr std::size_t kNodeOverhead = 48;

template <class T>
std::size_t vectorBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

/// A dense matrix or vector (Eigen's, or anything with size() and a Scalar type).
template <class Dense>
std::size_t denseBytes(const Dense& m) {
  return static_cast<std::size_t>(m.size()) * sizeof(typename Dense::Scalar);
}

template <class K, class V, class C, class A>
std::size_t mapBytes(const std::map<K, V, C, A>& m) {
  return m.size() * (sizeof(typename std::map<K, V, C, A>::value_type) + kNodeOverhead);
}

template <class K, class V, class H, class E, class A>
std::size_t mapBytes(const std::unordered_map<K, V, H, E, A>& m) {
  return m.size() * (sizeof(typename std::unordered_map<K, V, H, E, A>::value_type) + kNodeOverhead) +
         m.bucket_count() * sizeof(void*);
}

/// Σ over the inner vectors, with the outer vector's own room.
template <class T>
std::size_t nestedVectorBytes(const std::vector<std::vector<T>>& v) {
  std::size_t bytes = vectorBytes(v);
  for (const std::vector<T>& inner : v) bytes += vectorBytes(inner);
  return bytes;
}

}  // namespace semslam
