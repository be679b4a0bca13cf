//! Files that are not point lists at all: an SVG drawing, JSON, a compressed archive, an
//! image, UTF-16 text. Told apart by their first bytes, so that the message says what the
//! file is and what to do instead of calling its first token "not a number".
//!
//! Every kind recognised here would be refused anyway (its first byte is no number, no
//! header word and no `#`, or the data is not UTF-8): a file that reads as points is never
//! refused by this test.

use std::fmt;

/// What a file that is not a point list looks like (see [`ParseErrorKind::NotAPointFile`]).
///
/// [`ParseErrorKind::NotAPointFile`]: super::ParseErrorKind::NotAPointFile
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum FileKind {
    /// An SVG drawing (`<svg`, or an XML document whose start names `<svg`).
    Svg,
    /// An HTML page (`<!DOCTYPE html`, `<html`).
    Html,
    /// Any other XML document (`<?xml`, `<!DOCTYPE`, `<gpx`, `<kml`, ...).
    Xml,
    /// JSON or GeoJSON (`{` or `[`).
    Json,
    /// gzip-compressed data.
    Gzip,
    /// xz-, bzip2- or zstd-compressed data.
    Compressed,
    /// A ZIP archive (also an `.xlsx`, `.ods` or `.docx` document).
    Zip,
    /// A PDF document.
    Pdf,
    /// A PNG, JPEG or GIF image.
    Image,
    /// UTF-16 text (as Windows PowerShell's `>` writes it).
    Utf16,
}

impl FileKind {
    /// What to do instead, for the error message.
    pub fn advice(self) -> &'static str {
        match self {
            FileKind::Svg | FileKind::Html | FileKind::Xml | FileKind::Json => {
                "export the points as text (one `x y` per line) or CSV"
            }
            FileKind::Gzip => "decompress it first (e.g. `gzip -dc FILE | wdm-crust ...`)",
            FileKind::Compressed => "decompress it first (unxz, bunzip2 or unzstd)",
            FileKind::Zip => "extract the point file from it, or save the spreadsheet as CSV",
            FileKind::Pdf | FileKind::Image => {
                "the input is point coordinates as text (one `x y` per line) or CSV"
            }
            FileKind::Utf16 => {
                "save it as UTF-8 (in PowerShell: `... | Out-File -Encoding utf8 FILE`)"
            }
        }
    }
}

impl fmt::Display for FileKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FileKind::Svg => "an SVG drawing (XML)",
            FileKind::Html => "an HTML page",
            FileKind::Xml => "an XML document",
            FileKind::Json => "JSON (or GeoJSON)",
            FileKind::Gzip => "gzip-compressed data",
            FileKind::Compressed => "compressed data (xz, bzip2 or zstd)",
            FileKind::Zip => "a ZIP archive (an .xlsx or .ods spreadsheet is one)",
            FileKind::Pdf => "a PDF document",
            FileKind::Image => "an image (PNG, JPEG or GIF)",
            FileKind::Utf16 => "UTF-16 text",
        })
    }
}

/// How far into the head a markup document is searched for its root element.
const ROOT_SEARCH_BYTES: usize = 1024;

/// How many bytes of a file [`sniff`] is given: the root search after a byte-order mark
/// and some leading white space.
pub(super) const HEAD_BYTES: usize = 4096;

/// What the first bytes of a file say it is, when it is not a point list; `None` when they
/// could start one (or are too few to tell).
pub(super) fn sniff(head: &[u8]) -> Option<FileKind> {
    const MAGIC: [(&[u8], FileKind); 13] = [
        (b"\x1f\x8b", FileKind::Gzip),
        (b"\xfd7zXZ\x00", FileKind::Compressed),
        (b"BZh", FileKind::Compressed),
        (b"\x28\xb5\x2f\xfd", FileKind::Compressed),
        (b"PK\x03\x04", FileKind::Zip),
        (b"PK\x05\x06", FileKind::Zip),
        (b"%PDF-", FileKind::Pdf),
        (b"\x89PNG", FileKind::Image),
        (b"\xff\xd8\xff", FileKind::Image),
        (b"GIF87a", FileKind::Image),
        (b"GIF89a", FileKind::Image),
        (b"\xff\xfe", FileKind::Utf16),
        (b"\xfe\xff", FileKind::Utf16),
    ];
    for (magic, kind) in MAGIC {
        // `BZh` is followed by the block size digit; text starting `BZh` is no point file
        // either, but keep the claim exact.
        if head.starts_with(magic)
            && (magic != b"BZh" || head.get(3).is_some_and(|b| (b'1'..=b'9').contains(b)))
        {
            return Some(kind);
        }
    }
    // UTF-16 without a byte-order mark: ASCII with a NUL byte after (or before) each.
    if let [a, b, c, d, ..] = head {
        let ascii = |x: &u8| x.is_ascii_graphic() || x.is_ascii_whitespace();
        if (ascii(a) && *b == 0 && ascii(c) && *d == 0)
            || (*a == 0 && ascii(b) && *c == 0 && ascii(d))
        {
            return Some(FileKind::Utf16);
        }
    }
    let text = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let start = text.iter().position(|b| !b.is_ascii_whitespace())?;
    let text = &text[start..];
    match text[0] {
        b'{' | b'[' => Some(FileKind::Json),
        b'<' => markup(text),
        _ => None,
    }
}

/// The kind of a document starting with `<`: SVG, HTML or other XML (`<` then a letter,
/// `?` or `!`).
fn markup(text: &[u8]) -> Option<FileKind> {
    if !text
        .get(1)
        .is_some_and(|&b| b.is_ascii_alphabetic() || b == b'?' || b == b'!')
    {
        return None;
    }
    let window = text[..text.len().min(ROOT_SEARCH_BYTES)].to_ascii_lowercase();
    let contains = |needle: &[u8]| window.windows(needle.len()).any(|w| w == needle);
    if contains(b"<svg") || contains(b"<!doctype svg") {
        Some(FileKind::Svg)
    } else if contains(b"<html") || contains(b"<!doctype html") {
        Some(FileKind::Html)
    } else {
        Some(FileKind::Xml)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn documents_are_told_apart() {
        for (head, kind) in [
            (
                &b"<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\">"[..],
                FileKind::Svg,
            ),
            (b"\xEF\xBB\xBF  \r\n<svg width=\"10\">", FileKind::Svg),
            (
                b"<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\">",
                FileKind::Svg,
            ),
            (b"<!DOCTYPE html>\n<html>", FileKind::Html),
            (b"<HTML><BODY>", FileKind::Html),
            (
                b"<?xml version=\"1.0\"?><gpx version=\"1.1\">",
                FileKind::Xml,
            ),
            (b"<!-- points -->\n<kml>", FileKind::Xml),
            (b"{\"type\": \"FeatureCollection\"}", FileKind::Json),
            (b"\n [[0, 1], [2, 3]]", FileKind::Json),
            (b"\x1f\x8b\x08\x00", FileKind::Gzip),
            (b"BZh91AY&SY", FileKind::Compressed),
            (b"PK\x03\x04\x14\x00", FileKind::Zip),
            (b"%PDF-1.7\n", FileKind::Pdf),
            (b"\x89PNG\r\n\x1a\n", FileKind::Image),
            (b"\xff\xd8\xff\xe0", FileKind::Image),
            (b"GIF89a", FileKind::Image),
            (b"\xff\xfe1\x00 \x002\x00", FileKind::Utf16),
            (b"1\x00.\x005\x00", FileKind::Utf16),
        ] {
            assert_eq!(sniff(head), Some(kind), "{head:?}");
        }
    }

    #[test]
    fn point_files_are_not_claimed() {
        for head in [
            &b""[..],
            b"   \n",
            b"1 2\n3 4\n",
            b"\xEF\xBB\xBFx,y\n",
            b"# <svg> in a comment\n1 2\n",
            b"BZh 1 2",
            b"<",
            b"< 1 2",
            b"x\x00",
            b"-1.5e3,2\n",
        ] {
            assert_eq!(sniff(head), None, "{head:?}");
        }
    }
}
