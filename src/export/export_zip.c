/* SPDX-License-Identifier: BSD-3-Clause */
/* A minimal zip archive writer (docs/export.md, FMU): entries stored
 * uncompressed, CRC-32 from zlib, a fixed time stamp (1980-01-01) so the same
 * files give the same bytes. An FMU is a few tens of kilobytes; deflate would
 * save little and cost a dependency's worth of code paths. */
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "export/export.h"

static void le16(bg_strbuf *o, unsigned v) {
  bg_sb_putc(o, (char)(v & 0xff));
  bg_sb_putc(o, (char)((v >> 8) & 0xff));
}

static void le32(bg_strbuf *o, unsigned long v) {
  le16(o, (unsigned)(v & 0xffff));
  le16(o, (unsigned)((v >> 16) & 0xffff));
}

/* The fields the local and central headers share, from "version needed" on. */
static void common_fields(bg_strbuf *o, const bg_zip_entry *e, unsigned long crc, size_t name_len) {
  le16(o, 10);     /* version needed: 1.0, stored */
  le16(o, 0);      /* flags */
  le16(o, 0);      /* method: stored */
  le16(o, 0);      /* time 00:00:00 */
  le16(o, 0x21);   /* date 1980-01-01 */
  le32(o, crc);
  le32(o, (unsigned long)e->len); /* compressed size */
  le32(o, (unsigned long)e->len); /* uncompressed size */
  le16(o, (unsigned)name_len);
  le16(o, 0);      /* extra field length */
}

void bg_export_zip(const bg_zip_entry *e, int n, bg_strbuf *o) {
  unsigned long *crc = calloc((size_t)n + 1, sizeof *crc);
  size_t *offset = calloc((size_t)n + 1, sizeof *offset);
  for (int i = 0; i < n; i++) {
    crc[i] = crc32(crc32(0L, Z_NULL, 0), (const Bytef *)e[i].data, (uInt)e[i].len);
    offset[i] = o->len;
    le32(o, 0x04034b50);
    common_fields(o, &e[i], crc[i], strlen(e[i].name));
    bg_sb_puts(o, e[i].name);
    bg_sb_putn(o, e[i].data, e[i].len);
  }
  size_t cd = o->len;
  for (int i = 0; i < n; i++) {
    le32(o, 0x02014b50);
    le16(o, 0x0314); /* made by: Unix, 2.0 (so the permissions below count) */
    common_fields(o, &e[i], crc[i], strlen(e[i].name));
    le16(o, 0);      /* comment length */
    le16(o, 0);      /* disk */
    le16(o, 0);      /* internal attributes */
    le32(o, 0100644ul << 16); /* external: a regular file, rw-r--r-- */
    le32(o, (unsigned long)offset[i]);
    bg_sb_puts(o, e[i].name);
  }
  size_t cd_len = o->len - cd;
  le32(o, 0x06054b50);
  le16(o, 0), le16(o, 0); /* this disk, the central directory's disk */
  le16(o, (unsigned)n), le16(o, (unsigned)n);
  le32(o, (unsigned long)cd_len), le32(o, (unsigned long)cd);
  le16(o, 0);      /* comment length */
  free(crc), free(offset);
}
