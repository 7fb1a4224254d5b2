/* utf8.h — well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most
 * U+10FFFF), for text that must stay readable: the case file (libfyaml let a stray
 * Latin-1 byte end a document silently) and the names written into output files' comments
 * (XML refuses malformed UTF-8). */
#ifndef HVSPH_CORE_UTF8_H
#define HVSPH_CORE_UTF8_H

#include <stddef.h>

/* Bytes (1 to 4) of the well-formed character that starts s[0..len), 0 if none does (a
 * stray byte, an overlong form, a surrogate, beyond U+10FFFF, or cut short by len). */
size_t hv_utf8_char(const unsigned char *s, size_t len);

/* Length of the longest well-formed prefix of s[0..len): len when all of it is UTF-8,
 * else the offset of the first byte that is not. */
size_t hv_utf8_valid_prefix(const unsigned char *s, size_t len);

#endif
