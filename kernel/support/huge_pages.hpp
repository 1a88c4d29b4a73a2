// Advice that a block of memory be backed by transparent huge pages. The OS
// maps fresh memory a page at a time on its first write and takes those page
// faults one at a time, however many threads write: 16 MiB of 4 KiB pages
// took 8 ms on one thread and 5-9 ms on two here, in 2 MiB pages 2.4 ms.
// Internal to the library.
#pragma once

#include <cstddef>

namespace obbsat::detail {

/// Size of a huge page, and the least block worth advising.
constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;
constexpr std::size_t huge_page_threshold = 2 * huge_page_bytes;

/// Asks for huge pages for the whole huge pages inside [block, block + bytes)
/// when bytes >= huge_page_threshold. Advice only: nothing changes where the
/// OS has none, and the memory's contents are untouched.
void advise_huge_pages(void* block, std::size_t bytes) noexcept;

}  // namespace obbsat::detail
