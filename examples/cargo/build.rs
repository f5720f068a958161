//! Generates src's `circles` module from ../equations/circles.mxm into OUT_DIR, and tells Cargo
//! to rerun when the .mxm or anything it loads changes (read from max2code's depfile).
use std::env;
use std::fs;
use std::path::PathBuf;
use std::process::Command;

fn main() {
    let out = PathBuf::from(env::var("OUT_DIR").expect("OUT_DIR")).join("circles.rs");
    let depfile = PathBuf::from(format!("{}.d", out.display()));
    let command = env::var("MAX2CODE").unwrap_or_else(|_| "max2code".to_string());
    let mut words = command.split_whitespace();
    let program = words.next().expect("MAX2CODE is empty");
    let status = Command::new(program)
        .args(words)
        .args(["--lang=rust", "../equations/circles.mxm", "-o"])
        .arg(&out)
        .arg("-MF")
        .arg(&depfile)
        .status()
        .unwrap_or_else(|e| panic!("cannot run {command}: {e}"));
    assert!(status.success(), "max2code failed");
    for dep in depfile_dependencies(&fs::read_to_string(&depfile).expect("depfile")) {
        println!("cargo:rerun-if-changed={dep}");
    }
    println!("cargo:rerun-if-env-changed=MAX2CODE");
}

/// The prerequisites of the first rule of a Make depfile (backslash escapes, continuations).
fn depfile_dependencies(text: &str) -> Vec<String> {
    let rule = text.split("\n\n").next().unwrap_or("").replace("\\\n", " ");
    let after = match rule.find(": ") {
        Some(i) => &rule[i + 2..],
        None => return Vec::new(),
    };
    let mut deps = Vec::new();
    let mut word = String::new();
    let mut chars = after.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if matches!(chars.peek(), Some(' ') | Some('#') | Some(':') | Some('\\')) => {
                word.push(chars.next().unwrap())
            }
            '$' if chars.peek() == Some(&'$') => {
                chars.next();
                word.push('$')
            }
            c if c.is_whitespace() => {
                if !word.is_empty() {
                    deps.push(std::mem::take(&mut word))
                }
            }
            c => word.push(c),
        }
    }
    if !word.is_empty() {
        deps.push(word)
    }
    deps
}
