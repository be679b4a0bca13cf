//! Splitting one line into fields.
//!
//! A line with a comma (outside double quotes) is split at its commas, and only there: white
//! space around a field is trimmed, white space inside one stays in it. A line without a
//! comma is split at runs of white space. So `1.5, 2` and `1.5 2` are both two fields, while a
//! line with decimal commas, `0,5 1,5`, splits into `0`, `5 1` and `5`, and the middle field is
//! then refused as a number instead of the line being read as the point (0, 5). A field may
//! be quoted (`"x"`, `"1.5"`); the quotes are removed.

/// White space between fields (line ends never reach the splitter).
#[inline]
pub(super) fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\x0b' | b'\x0c')
}

/// [`is_blank`] for `char`s.
#[inline]
pub(super) fn is_blank_char(c: char) -> bool {
    c.is_ascii() && is_blank(c as u8)
}

/// How a line is split: whether it has a comma outside double quotes, and if so, whether it
/// has a quote at all.
#[inline]
fn separators(line: &str) -> (bool, bool) {
    let bytes = line.as_bytes();
    // The common cases first, with the fast byte search: no comma, or no quote.
    if !bytes.contains(&b',') {
        return (false, false);
    }
    if !bytes.contains(&b'"') {
        return (true, false);
    }
    let mut quoted = false;
    for &b in bytes {
        match b {
            b'"' => quoted = !quoted,
            b',' if !quoted => return (true, true),
            _ => {}
        }
    }
    (false, true)
}

/// `text` without white space at either end.
#[inline]
fn trim_blanks(text: &str) -> &str {
    let bytes = text.as_bytes();
    let (mut start, mut end) = (0, bytes.len());
    while start < end && is_blank(bytes[start]) {
        start += 1;
    }
    while end > start && is_blank(bytes[end - 1]) {
        end -= 1;
    }
    // White space is ASCII: both ends are on character boundaries.
    &text[start..end]
}

/// A field without its surrounding white space and quotes.
#[inline]
fn unquote(field: &str) -> &str {
    let field = trim_blanks(field);
    match field.strip_prefix('"').and_then(|f| f.strip_suffix('"')) {
        Some(inner) => trim_blanks(inner),
        None => field,
    }
}

/// The fields of a line with its comment and surrounding white space removed (see the
/// [module docs](self)). In a comma-separated line a field may be empty (`1,,2`, `1,2,`).
pub(super) struct Fields<'a> {
    rest: &'a str,
    commas: bool,
    quotes: bool,
    done: bool,
}

impl<'a> Fields<'a> {
    pub(super) fn new(line: &'a str) -> Self {
        let (commas, quotes) = separators(line);
        Fields {
            rest: line,
            commas,
            quotes,
            done: false,
        }
    }

    /// The next field of a comma-separated line: up to the next comma outside quotes.
    fn next_comma_field(&mut self) -> &'a str {
        let bytes = self.rest.as_bytes();
        if !self.quotes {
            return match bytes.iter().position(|&b| b == b',') {
                Some(i) => {
                    let field = &self.rest[..i];
                    self.rest = &self.rest[i + 1..];
                    trim_blanks(field)
                }
                None => {
                    self.done = true;
                    trim_blanks(self.rest)
                }
            };
        }
        let mut quoted = false;
        for (i, &b) in bytes.iter().enumerate() {
            match b {
                b'"' => quoted = !quoted,
                b',' if !quoted => {
                    let field = &self.rest[..i];
                    self.rest = &self.rest[i + 1..];
                    return unquote(field);
                }
                _ => {}
            }
        }
        self.done = true;
        unquote(self.rest)
    }

    /// The next field of a white-space separated line, or `None` at its end.
    fn next_blank_field(&mut self) -> Option<&'a str> {
        let bytes = self.rest.as_bytes();
        let n = bytes.len();
        let mut start = 0;
        while start < n && is_blank(bytes[start]) {
            start += 1;
        }
        if start == n {
            self.done = true;
            return None;
        }
        if bytes[start] == b'"' {
            // A quoted field ends at its closing quote, if white space or the end follows.
            if let Some(len) = self.rest[start + 1..].find('"') {
                let after = start + len + 2;
                if after == n || is_blank(bytes[after]) {
                    let field = &self.rest[start..after];
                    self.rest = &self.rest[after..];
                    return Some(unquote(field));
                }
            }
        }
        let mut end = start + 1;
        while end < n && !is_blank(bytes[end]) {
            end += 1;
        }
        // White space is ASCII: `start` and `end` are on character boundaries.
        let field = &self.rest[start..end];
        self.rest = &self.rest[end..];
        Some(field)
    }
}

impl<'a> Iterator for Fields<'a> {
    type Item = &'a str;

    #[inline]
    fn next(&mut self) -> Option<&'a str> {
        if self.done {
            None
        } else if self.commas {
            Some(self.next_comma_field())
        } else {
            self.next_blank_field()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fields(line: &str) -> Vec<&str> {
        Fields::new(line).collect()
    }

    #[test]
    fn commas_split_only_at_commas() {
        assert_eq!(fields("1,2"), ["1", "2"]);
        assert_eq!(fields("5 ,  6"), ["5", "6"]);
        assert_eq!(fields("1,,2"), ["1", "", "2"]);
        assert_eq!(fields("1,2,"), ["1", "2", ""]);
        assert_eq!(fields(",x,y"), ["", "x", "y"]);
        assert_eq!(fields("0,5 1,5"), ["0", "5 1", "5"]);
        assert_eq!(fields("0,5;1,5"), ["0", "5;1", "5"]);
        assert_eq!(fields("New York, 1, 2"), ["New York", "1", "2"]);
    }

    #[test]
    fn white_space_splits_a_line_without_commas() {
        assert_eq!(fields("1 2"), ["1", "2"]);
        assert_eq!(fields("1\t \x0b2\x0c3"), ["1", "2", "3"]);
        assert_eq!(fields("x"), ["x"]);
    }

    #[test]
    fn quotes() {
        assert_eq!(fields("\"x\",\"y\""), ["x", "y"]);
        assert_eq!(fields("\"a,b\",1,2"), ["a,b", "1", "2"]);
        assert_eq!(fields("\"New York\" 1 2"), ["New York", "1", "2"]);
        assert_eq!(fields("\" 1.5 \" 2"), ["1.5", "2"]);
        assert_eq!(fields("\"1\"x 2"), ["\"1\"x", "2"]);
        assert_eq!(fields("\"1 2"), ["\"1", "2"]);
        assert_eq!(fields("\"1,5\",\"2,5\""), ["1,5", "2,5"]);
    }
}
