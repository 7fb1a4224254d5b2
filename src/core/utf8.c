/* utf8.c — see utf8.h. */
#include "core/utf8.h"

size_t hv_utf8_char(const unsigned char *s, size_t len)
{
  if (len == 0) return 0;
  const unsigned c = s[0];
  if (c < 0x80) return 1;
  size_t n;                      /* continuation bytes */
  unsigned lo = 0x80, hi = 0xbf; /* range of the second byte */
  if (c >= 0xc2 && c <= 0xdf) {
    n = 1;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 2;
    if (c == 0xe0) lo = 0xa0; /* overlong */
    if (c == 0xed) hi = 0x9f; /* surrogates */
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 3;
    if (c == 0xf0) lo = 0x90; /* overlong */
    if (c == 0xf4) hi = 0x8f; /* beyond U+10FFFF */
  } else {
    return 0;
  }
  if (len <= n || s[1] < lo || s[1] > hi) return 0;
  for (size_t k = 2; k <= n; k++)
    if (s[k] < 0x80 || s[k] > 0xbf) return 0;
  return n + 1;
}

size_t hv_utf8_valid_prefix(const unsigned char *s, size_t len)
{
  size_t i = 0;
  while (i < len) {
    const size_t n = hv_utf8_char(s + i, len - i);
    if (!n) return i;
    i += n;
  }
  return len;
}
