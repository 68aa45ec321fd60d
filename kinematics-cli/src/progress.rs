//! Progress of long work (`check` on a chain of thousands of joints takes minutes), on stderr and
//! only when stderr is a terminal: piped or redirected, the command writes exactly what it wrote
//! before progress existed.
//!
//! With indicatif: a spinner while the compiler or the build API runs (they report no progress),
//! and a bar over the configurations `check` and `demo` compare.

use std::io::IsTerminal;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The bar's layout: stage, bar, count, rate and time left.
const BAR_TEMPLATE: &str = "{msg} [{bar:32}] {human_pos}/{human_len} ({per_sec}, {eta} left)";
/// A stage of unknown length: spinner, stage, time so far.
const SPINNER_TEMPLATE: &str = "{spinner} {msg} ({elapsed})";

/// Whether progress is drawn: stderr is a terminal.
fn shown() -> bool {
    std::io::stderr().is_terminal()
}

/// A style from a template of this file; the templates are constants, checked by a unit test, so
/// the fallback (indicatif's plain default) is never taken in practice.
fn style(template: &str, fallback: fn() -> ProgressStyle) -> ProgressStyle {
    ProgressStyle::with_template(template).unwrap_or_else(|_| fallback())
}

/// A bar of `len` steps labelled `stage`, hidden unless stderr is a terminal. Call
/// [`ProgressBar::finish_and_clear`] when done, so nothing of it stays on the screen.
pub fn bar(len: u64, stage: &str) -> ProgressBar {
    if !shown() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::stderr());
    bar.set_style(style(BAR_TEMPLATE, ProgressStyle::default_bar).progress_chars("=> "));
    bar.set_message(stage.to_owned());
    bar
}

/// A spinner labelled `stage` for work inside a library call that reports no progress, hidden
/// unless stderr is a terminal; it turns on its own while the call runs.
pub fn spinner(stage: &str) -> ProgressBar {
    if !shown() {
        return ProgressBar::hidden();
    }
    let spinner = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    spinner.set_style(style(SPINNER_TEMPLATE, ProgressStyle::default_spinner));
    spinner.set_message(stage.to_owned());
    spinner.enable_steady_tick(Duration::from_millis(120));
    spinner
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_templates_parse() {
        assert!(ProgressStyle::with_template(BAR_TEMPLATE).is_ok());
        assert!(ProgressStyle::with_template(SPINNER_TEMPLATE).is_ok());
    }
}
