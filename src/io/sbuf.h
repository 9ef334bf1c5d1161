/*
** src/io/sbuf.h -- a growing text buffer, with XML and JSON escaping
** See LICENSE for copyright and license.
**
** The SVG and HTML writers build their documents here and hand them to an
** output file in one piece.  An allocation failure does not stop the calls:
** it sets sb->failed, later appends do nothing, and the caller checks failed
** once at the end.
*/
#ifndef PT_SBUF_H
#define PT_SBUF_H

#include <stddef.h>

typedef struct pt_sbuf {
    char *s;                     /* the text, NUL-terminated (NULL while empty); owned */
    size_t len, cap;             /* length, and bytes allocated */
    int failed;                  /* 1 after an allocation failed */
} pt_sbuf;

/* Start empty.  This function can't fail. */
void pt_sbuf_init(pt_sbuf *sb);

/* Free the text and start empty again.  This function can't fail. */
void pt_sbuf_free(pt_sbuf *sb);

/* Append the string t.  On allocation failure sets sb->failed. */
void pt_sbuf_add(pt_sbuf *sb, const char *t);

/* Append n bytes at t. */
void pt_sbuf_addn(pt_sbuf *sb, const char *t, size_t n);

/* Append printf(fmt, ...) ("C" locale formats, as pipetrace never sets one). */
void pt_sbuf_addf(pt_sbuf *sb, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Length of the well-formed UTF-8 sequence at p (RFC 3629: no overlong
** forms, no surrogates, at most U+10FFFF; reads no byte past a NUL), or 0 when
** it is not one.  This function can't fail. */
int pt_sbuf_utf8_len(const unsigned char *p);

/* Append t as XML or HTML character data or attribute value, the one
** function for untrusted text in every SVG and HTML writer: & < > " ' become
** entities; well-formed UTF-8 passes through unchanged but for what XML 1.0
** or HTML forbids raw (control characters other than tab and newline, DEL,
** C1, U+FFFE, U+FFFF and the other noncharacters), which, as a byte that is
** not part of a well-formed character, becomes U+FFFD. */
void pt_sbuf_add_xml(pt_sbuf *sb, const char *t);

/* Append t as a JSON string, quotes included.  Besides " \ and control
** characters, a '<' before '/' or '!' is written \u003c, so the string can sit
** inside an HTML <script> element ("</script" or "<!--" would end it); what
** pt_sbuf_add_xml() refuses is written as \uXXXX (the same character, in
** ASCII).  Bad UTF-8 becomes U+FFFD. */
void pt_sbuf_add_json(pt_sbuf *sb, const char *t);

/* 1 when t[0..n) may go to a terminal as it is: well-formed UTF-8 with no
** control character (C0, DEL, C1: an escape sequence begins with one) and no
** character that turns or hides text (the bidirectional controls U+202A ..
** U+202E and U+2066 .. U+2069, U+200E, U+200F, U+FEFF).  This function
** can't fail. */
int pt_sbuf_term_plain(const char *t, size_t n);

/* Append t[0..n) made safe for a terminal, the one function for text from an
** untrusted file that reaches one: what pt_sbuf_term_plain() refuses is
** written out visibly, a byte as \xHH, a character as \uHHHH; a backslash
** as \\ where anything is written out, so the result reads back. */
void pt_sbuf_add_term(pt_sbuf *sb, const char *t, size_t n);

/* 1 when text t goes into a CSV cell as it is: no comma, quote, CR or LF,
** and no first character a spreadsheet reads as a formula (= + - @, tab,
** CR).  This function can't fail. */
int pt_sbuf_csv_plain(const char *t);

/* Append t as one CSV cell (RFC 4180), the one quoting every CSV writer uses:
** as it is when pt_sbuf_csv_plain(t); else between double quotes, each quote
** doubled, and a formula's first character behind a single quote (the
** spreadsheet tools' convention: '=1+1 is text). */
void pt_sbuf_add_csv(pt_sbuf *sb, const char *t);

/* Append untrusted text t (a file's name, a message quoting one) as one CSV
** cell: made safe for a terminal first (pt_sbuf_add_term()), since a CSV
** goes to standard output as often as to a file, then as pt_sbuf_add_csv(). */
void pt_sbuf_add_csv_untrusted(pt_sbuf *sb, const char *t);

#endif
