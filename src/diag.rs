//! Errors and warnings about scenes, rendered with a caret under the source and the chain of
//! includes and macro calls that led to the place.

use codespan_reporting::diagnostic::{Diagnostic as CsDiag, Label};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream, WriteColor};
use codespan_reporting::term::{self, Config};

use crate::sdl::source::{Sources, Span};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

/// How the place was reached: "included from" or "in macro called from".
#[derive(Clone, Debug)]
pub struct ChainLink {
    pub what: String,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Diagnostic {
    pub severity: Severity,
    pub message: String,
    pub span: Option<Span>,
    pub chain: Vec<ChainLink>,
    pub notes: Vec<String>,
    /// A warning about something declared that lancer cannot render: it may wait until the
    /// declared identifier is used (see the parser's `defer_warnings`).
    pub deferrable: bool,
}

impl Diagnostic {
    pub fn error(message: impl Into<String>, span: Option<Span>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            message: message.into(),
            span,
            chain: Vec::new(),
            notes: Vec::new(),
            deferrable: false,
        }
    }
    pub fn warning(message: impl Into<String>, span: Option<Span>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            message: message.into(),
            span,
            chain: Vec::new(),
            notes: Vec::new(),
            deferrable: false,
        }
    }
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// Plain one-line form, `file:line:col: error: message`, used in tests and logs.
    pub fn one_line(&self, sources: &Sources) -> String {
        let sev = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        match self.span {
            Some(s) => format!("{}: {sev}: {}", sources.place(s), self.message),
            None => format!("{sev}: {}", self.message),
        }
    }

    pub fn emit(&self, sources: &Sources, out: &mut dyn WriteColor) {
        let mut d = match self.severity {
            Severity::Error => CsDiag::error(),
            Severity::Warning => CsDiag::warning(),
        };
        let mut message = self.message.clone();
        let mut labels = Vec::new();
        if let Some(s) = self.span {
            // codespan prints line:col next to the file; keep the one-line form in the message
            // head too so logs grepped for file:line find it.
            message = format!("{} ({})", self.message, sources.place(s));
            labels.push(Label::primary(
                s.file as usize,
                s.start as usize..s.end.max(s.start + 1) as usize,
            ));
        }
        for link in &self.chain {
            labels.push(
                Label::secondary(
                    link.span.file as usize,
                    link.span.start as usize..link.span.end as usize,
                )
                .with_message(link.what.clone()),
            );
        }
        d = d
            .with_message(message)
            .with_labels(labels)
            .with_notes(self.notes.clone());
        let config = Config::default();
        if term::emit(out, &config, &sources.files, &d).is_err() {
            // Spans that fall outside the file (should not happen) still get a readable line.
            let _ = std::io::Write::write_fmt(out, format_args!("{}\n", self.one_line(sources)));
        }
    }

    pub fn emit_stderr(&self, sources: &Sources) {
        let choice = if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
            ColorChoice::Auto
        } else {
            ColorChoice::Never
        };
        let mut stream = StandardStream::stderr(choice);
        self.emit(sources, &mut stream);
    }
}
