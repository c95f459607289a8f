//! Literal number lists of `mesh2` read straight from the text, without a token per number.
//!
//! A mesh2 written by a program holds millions of `<x, y, z>,` entries: seven tokens of 40
//! bytes each per vertex (a 1,000,000-triangle mesh2 made 12.5 million tokens, 500 MB, more
//! than POV-Ray's whole run). When the list after `vertex_vectors {` (and the other mesh2
//! lists) is nothing but literals in the plain shape a program writes, the lexer stores its
//! numbers in one [`Bulk`] token instead. Any other text (an identifier, an operator, a
//! directive, a comma left out, a count that does not match the entries) keeps the ordinary
//! tokens, so the parser reads it with full expressions and its usual errors: the plain shape
//! is exactly the one whose meaning does not depend on how expressions are read.

use super::lexer::number_value;

/// The mesh2 lists whose entries may be stored in bulk, and the vector sizes each allows.
pub(super) fn list_kind(keyword: &str) -> Option<Kind> {
    Some(match keyword {
        "vertex_vectors" | "normal_vectors" => Kind::Vectors,
        "uv_vectors" => Kind::UvVectors,
        "normal_indices" | "uv_indices" => Kind::Indices,
        "face_indices" => Kind::Faces,
        _ => return None,
    })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Vectors,
    UvVectors,
    Indices,
    /// Index vectors each followed by up to three texture indices.
    Faces,
}

/// The entries of one literal list: the count written first and one 3-vector per entry (a
/// 2-vector gets z = 0, as a vector expression is padded); `first_texture` is empty unless some
/// face gave texture indices, then it holds the first of them per face (NaN: none).
#[derive(Debug, PartialEq)]
pub struct Bulk {
    pub count: f64,
    pub vectors: Vec<[f64; 3]>,
    pub first_texture: Vec<f64>,
}

/// Reads the list that starts just after its `{` in `s`; on success returns the entries and
/// the text from the closing `}` on (not consumed). `None` leaves the list to the tokens.
pub(super) fn scan(s: &str, kind: Kind) -> Option<(Bulk, &str)> {
    let mut c = Cursor { s };
    c.trivia()?;
    let count = c.signed_number()?;
    if !(count >= 1.0 && count <= u32::MAX as f64) {
        return None;
    }
    let mut out = Bulk {
        count,
        vectors: Vec::with_capacity((count as usize).min(1 << 24)),
        first_texture: Vec::new(),
    };
    let mut textured = false;
    loop {
        // After the count and after every entry: a comma, or the closing brace after the last.
        c.trivia()?;
        if c.s.starts_with('}') {
            break;
        }
        c.expect(b',')?;
        c.trivia()?;
        if c.s.starts_with('}') {
            break;
        }
        out.vectors.push(c.vector(kind)?);
        if kind == Kind::Faces {
            let tex = c.textures()?;
            if tex.is_some() && !textured {
                textured = true;
                out.first_texture = vec![f64::NAN; out.vectors.len() - 1];
            }
            if textured {
                out.first_texture.push(tex.unwrap_or(f64::NAN));
            }
        }
    }
    (out.vectors.len() as f64 == count).then_some((out, c.s))
}

struct Cursor<'a> {
    s: &'a str,
}

impl<'a> Cursor<'a> {
    /// White space and comments; `None` for anything the list scan leaves to the tokens (an
    /// unclosed comment is the lexer's error to report).
    fn trivia(&mut self) -> Option<()> {
        loop {
            self.s = self.s.trim_start();
            if let Some(r) = self.s.strip_prefix("//") {
                self.s = r.find('\n').map_or("", |i| &r[i..]);
            } else if self.s.starts_with("/*") {
                return None;
            } else {
                return Some(());
            }
        }
    }

    fn expect(&mut self, b: u8) -> Option<()> {
        let r = self.s.strip_prefix(b as char)?;
        self.s = r;
        Some(())
    }

    /// A literal with an optional sign (a unary minus of a literal is that literal negated
    /// exactly); what follows must end it: space, comma, `>` or `}`.
    fn signed_number(&mut self) -> Option<f64> {
        let neg = match self.s.as_bytes().first()? {
            b'-' => true,
            b'+' => false,
            _ => return self.number(),
        };
        self.s = &self.s[1..];
        self.trivia()?;
        let v = self.number()?;
        Some(if neg { -v } else { v })
    }

    fn number(&mut self) -> Option<f64> {
        let (v, rest) = number_value(self.s)?;
        match rest.as_bytes().first() {
            None => return None,
            Some(b) if b.is_ascii_whitespace() || matches!(b, b',' | b'>' | b'}' | b'/') => {}
            Some(_) => return None,
        }
        self.s = rest;
        Some(v)
    }

    fn vector(&mut self, kind: Kind) -> Option<[f64; 3]> {
        self.expect(b'<')?;
        let mut v = [0.0; 3];
        let mut n = 0;
        loop {
            self.trivia()?;
            if n == 3 {
                return None;
            }
            v[n] = self.signed_number()?;
            n += 1;
            self.trivia()?;
            if self.s.starts_with('>') {
                self.s = &self.s[1..];
                break;
            }
            self.expect(b',')?;
        }
        let ok = match kind {
            Kind::UvVectors => n >= 2,
            _ => n == 3,
        };
        ok.then_some(v)
    }

    /// A face's texture indices: `, t` or `, t1, t2, t3` after its vector, each a literal
    /// followed by a comma or the closing brace (so the comma before the next face, or before
    /// the brace, is left for the list loop).
    fn textures(&mut self) -> Option<Option<f64>> {
        let mut first = None;
        for _ in 0..3 {
            let save = self.s;
            self.trivia()?;
            if self.expect(b',').is_none() {
                self.s = save;
                return Some(first);
            }
            self.trivia()?;
            if !self
                .s
                .starts_with(|c: char| c.is_ascii_digit() || matches!(c, '.' | '-' | '+'))
            {
                self.s = save;
                return Some(first);
            }
            let t = self.signed_number()?;
            first.get_or_insert(t);
        }
        // A fourth number after three texture indices would start the next face as a float.
        let save = self.s;
        self.trivia()?;
        if self.expect(b',').is_some() {
            self.trivia()?;
            if !self.s.starts_with(['<', '}']) {
                return None;
            }
        }
        self.s = save;
        Some(first)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_lists_are_read() {
        let (b, rest) = scan(" 2, <1, -2, .5e1>, < 0,0,1 > , } x", Kind::Vectors).unwrap();
        assert_eq!(b.count, 2.0);
        assert_eq!(b.vectors, vec![[1.0, -2.0, 5.0], [0.0, 0.0, 1.0]]);
        assert_eq!(rest, "} x");
        let (b, _) = scan("2,<0,1>,<1,1> // uv\n}", Kind::UvVectors).unwrap();
        assert_eq!(b.vectors, vec![[0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]);
    }

    #[test]
    fn face_textures_keep_the_first() {
        let (b, _) = scan("3, <0,1,2>, 4, <1,2,3>, <2,3,4>, 5, 6, 7 }", Kind::Faces).unwrap();
        assert_eq!(b.vectors.len(), 3);
        assert_eq!(b.first_texture[0], 4.0);
        assert!(b.first_texture[1].is_nan());
        assert_eq!(b.first_texture[2], 5.0);
        let (b, _) = scan("1, <0,1,2> }", Kind::Faces).unwrap();
        assert!(b.first_texture.is_empty());
    }

    #[test]
    fn anything_else_is_left_to_the_tokens() {
        for s in [
            "2, <1,2,3>, <4,5,6> <7,8,9> }", // count mismatch
            "1 <1,2,3> }",                   // no comma after the count: `1 < 1` is an expression
            "1, <1,2,3> <4,5,6> }",          // no comma between entries
            "1, <1,2,3>*2 }",                // an operator
            "1, <1,2-1,3> }",                // an expression inside
            "1, <1,2,3>, #if (1) #end }",    // a directive
            "1, <a,2,3> }",                  // an identifier
            "1, <1,2> }",                    // a 2-vector where 3 are written by programs
            "1, <1,2,3>, /* c */ }",         // block comments: left to the lexer
            "0 }",                           // empty
        ] {
            assert!(scan(s, Kind::Vectors).is_none(), "{s}");
        }
        assert!(scan("1, <0,1,2>, 1, 2, 3, 4 }", Kind::Faces).is_none());
        assert!(scan("1, <0,1,2>, 1 2 }", Kind::Faces).is_none());
    }
}
