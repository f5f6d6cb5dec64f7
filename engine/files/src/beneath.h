// Opening a name content wrote beneath its folder, never outside it (read_file.cpp's
// readFileInside). Internal: the tests run every rule through both ways.
#pragma once
#include <string>

namespace platon::files {

// Opens `name` for reading beneath the folder open as `folder` (O_PATH), by the kernel's rules of
// RESOLVE_BENEATH: a link is followed while it stays beneath; an absolute link, a '..' above the
// folder or /proc's magic links are refused (EXDEV, ELOOP). Returns the descriptor, or -1 with
// errno. Uses openat2, or openWalking where the kernel has none (before Linux 5.6) or a seccomp
// filter refuses it.
int openBeneath(int folder, const std::string& name);

// The same rules, walked a part at a time in user space: each part opened with O_NOFOLLOW (so a
// part swapped for a link after it was looked at is refused, not followed), each link read and
// its target walked in its place, at most 40 of them.
int openWalking(int folder, const std::string& name);

// readFileInside (read_file.h) with `openName` for the opening: openBeneath, or openWalking.
std::string readInside(const std::string& folder, const std::string& name, size_t maxBytes,
                       int (*openName)(int, const std::string&));

}  // namespace platon::files
