//! A line splitter over any [`BufRead`] that accepts `\n`, `\r\n` and lone `\r` line ends,
//! reuses one buffer for every line and rejects binary input (NUL bytes, invalid UTF-8,
//! absurdly long lines) with the number of the offending line.

use std::io::{self, BufRead};

use super::parse::{ParseError, ParseErrorKind};

/// Longest line accepted, in bytes. Point files have lines of a few dozen bytes; anything
/// near this limit is binary data without line breaks.
pub(crate) const MAX_LINE_BYTES: usize = 1 << 20;

/// The UTF-8 byte order mark some Windows tools put at the start of a text file.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Yields the lines of a reader one at a time as `&str`, numbered from 1.
pub(crate) struct LineReader<R> {
    reader: R,
    line: Vec<u8>,
    /// Number of the line last returned (0 before the first).
    line_number: usize,
    /// The previous line ended with `\r`: a `\n` right after it belongs to the same line end.
    after_cr: bool,
}

impl<R: BufRead> LineReader<R> {
    /// Wraps `reader`.
    pub(crate) fn new(reader: R) -> Self {
        LineReader {
            reader,
            line: Vec::with_capacity(128),
            line_number: 0,
            after_cr: false,
        }
    }

    /// The next line's number and text without its line end, or `None` at the end of the
    /// input. A final line without a line end is returned like any other; an empty one is not.
    pub(crate) fn next_line(&mut self) -> Result<Option<(usize, &str)>, ParseError> {
        self.line.clear();
        let this_line = self.line_number + 1;
        let fail = |kind| ParseError {
            line: Some(this_line),
            kind,
        };
        loop {
            let buf = match self.reader.fill_buf() {
                Ok(buf) => buf,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(fail(ParseErrorKind::Io(e))),
            };
            if buf.is_empty() {
                if self.line.is_empty() {
                    return Ok(None);
                }
                break;
            }
            if self.after_cr {
                self.after_cr = false;
                if buf[0] == b'\n' {
                    self.reader.consume(1);
                    continue;
                }
            }
            match find_line_end(buf) {
                Some(i) => {
                    let end = buf[i];
                    if end == 0 {
                        return Err(fail(ParseErrorKind::NulByte));
                    }
                    self.line.extend_from_slice(&buf[..i]);
                    self.reader.consume(i + 1);
                    self.after_cr = end == b'\r';
                    break;
                }
                None => {
                    let n = buf.len();
                    self.line.extend_from_slice(buf);
                    self.reader.consume(n);
                }
            }
            if self.line.len() > MAX_LINE_BYTES {
                return Err(fail(ParseErrorKind::LineTooLong {
                    limit: MAX_LINE_BYTES,
                }));
            }
        }
        if self.line.len() > MAX_LINE_BYTES {
            return Err(fail(ParseErrorKind::LineTooLong {
                limit: MAX_LINE_BYTES,
            }));
        }
        self.line_number = this_line;
        let mut bytes = &self.line[..];
        if this_line == 1 && bytes.starts_with(BOM) {
            bytes = &bytes[BOM.len()..];
        }
        std::str::from_utf8(bytes)
            .map(|line| Some((this_line, line)))
            .map_err(|_| fail(ParseErrorKind::InvalidUtf8))
    }
}

/// Position of the first `\n`, `\r` or NUL byte, eight bytes at a time.
#[inline]
fn find_line_end(buf: &[u8]) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGHS: u64 = 0x8080_8080_8080_8080;
    // Non-zero exactly when some byte of `v` is zero.
    let zero_byte = |v: u64| v.wrapping_sub(ONES) & !v & HIGHS;
    let mut start = 0;
    for chunk in buf.chunks_exact(8) {
        let v = u64::from_le_bytes(chunk.try_into().unwrap_or([0; 8]));
        if zero_byte(v)
            | zero_byte(v ^ (ONES * u64::from(b'\n')))
            | zero_byte(v ^ (ONES * u64::from(b'\r')))
            != 0
        {
            break;
        }
        start += 8;
    }
    buf[start..]
        .iter()
        .position(|&b| b == b'\n' || b == b'\r' || b == 0)
        .map(|i| start + i)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(input: &[u8], capacity: usize) -> Vec<(usize, String)> {
        let reader = io::BufReader::with_capacity(capacity, input);
        let mut lr = LineReader::new(reader);
        let mut out = Vec::new();
        while let Some((number, line)) = lr.next_line().unwrap() {
            out.push((number, line.to_string()));
        }
        out
    }

    #[test]
    fn all_line_ends_at_every_buffer_size() {
        let input = b"a\nb\r\nc\rd\r\re\n\nf";
        let expected: Vec<(usize, String)> = ["a", "b", "c", "d", "", "e", "", "f"]
            .iter()
            .enumerate()
            .map(|(i, s)| (i + 1, s.to_string()))
            .collect();
        for capacity in 1..=input.len() + 1 {
            assert_eq!(lines(input, capacity), expected, "capacity {capacity}");
        }
    }

    #[test]
    fn line_end_search_agrees_with_a_plain_scan() {
        let mut buf = vec![b'x'; 40];
        assert_eq!(find_line_end(&buf), None);
        for end in [b'\n', b'\r', 0] {
            for i in 0..buf.len() {
                buf[i] = end;
                assert_eq!(find_line_end(&buf), Some(i));
                assert_eq!(find_line_end(&buf[..i]), None);
                buf[i] = 0x80 | end;
            }
        }
    }

    #[test]
    fn final_line_end_is_optional() {
        assert_eq!(lines(b"a\n", 8), vec![(1, "a".to_string())]);
        assert_eq!(lines(b"a", 8), vec![(1, "a".to_string())]);
        assert_eq!(lines(b"a\r\n", 2), vec![(1, "a".to_string())]);
        assert!(lines(b"", 8).is_empty());
    }

    #[test]
    fn byte_order_mark_is_skipped() {
        assert_eq!(lines(b"\xEF\xBB\xBFx\n", 2), vec![(1, "x".to_string())]);
    }

    #[test]
    fn binary_input_is_refused_with_its_line() {
        let mut lr = LineReader::new(&b"1 2\n3\x004\n"[..]);
        assert!(lr.next_line().unwrap().is_some());
        let err = lr.next_line().unwrap_err();
        assert_eq!(err.line, Some(2));
        assert!(matches!(err.kind, ParseErrorKind::NulByte));

        let mut lr = LineReader::new(&b"1 2\r\xFF\xFE\n"[..]);
        assert!(lr.next_line().unwrap().is_some());
        let err = lr.next_line().unwrap_err();
        assert_eq!(err.line, Some(2));
        assert!(matches!(err.kind, ParseErrorKind::InvalidUtf8));

        let long = vec![b'7'; MAX_LINE_BYTES + 10];
        let mut lr = LineReader::new(&long[..]);
        let err = lr.next_line().unwrap_err();
        assert_eq!(err.line, Some(1));
        assert!(matches!(err.kind, ParseErrorKind::LineTooLong { .. }));
    }
}
