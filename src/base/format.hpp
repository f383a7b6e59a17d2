// How numbers read in Atrium's messages, tables and overlay: byte sizes in the
// unit a user reads ("775.4 MiB") and counts with thousands grouped
// ("4,000,000,000"). The lowest layer: every other one may use it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace atrium {

// "640 bytes", "12.0 KiB", "775.4 MiB", "1.5 GiB".
[[nodiscard]] inline std::string format_bytes(double bytes) {
  char text[64];
  if (bytes >= 1024.0 * 1024.0 * 1024.0) std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  else if (bytes >= 1024.0 * 1024.0) std::snprintf(text, sizeof text, "%.1f MiB", bytes / (1024.0 * 1024.0));
  else if (bytes >= 1024.0) std::snprintf(text, sizeof text, "%.1f KiB", bytes / 1024.0);
  else std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  return text;
}

// "4,000,000,000".
[[nodiscard]] inline std::string with_commas(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string grouped;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
    grouped += digits[i];
  }
  return grouped;
}

}  // namespace atrium
