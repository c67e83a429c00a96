//! A minimal Markdown → HTML renderer for the interpretation register in `index.html`:
//! headings, paragraphs, bullet and numbered lists, tables, fenced code, and inline `code`,
//! **bold**, *italic* and [links](…) (shown as their text). Everything is HTML-escaped first;
//! anything else passes through as text.

/// Escapes text for HTML element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Inline markup of one run of text.
pub fn inline(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if c == '\\' {
            if let Some(next) = rest[1..].chars().next().filter(|n| n.is_ascii_punctuation()) {
                out.push_str(&escape(&next.to_string()));
                rest = &rest[1 + next.len_utf8()..];
                continue;
            }
        }
        if c == '`' {
            if let Some(end) = rest[1..].find('`') {
                out.push_str(&format!("<code>{}</code>", escape(&rest[1..1 + end])));
                rest = &rest[end + 2..];
                continue;
            }
        }
        if rest.starts_with("**") {
            if let Some(end) = rest[2..].find("**") {
                out.push_str(&format!("<strong>{}</strong>", inline(&rest[2..2 + end])));
                rest = &rest[end + 4..];
                continue;
            }
        }
        if c == '*' && !rest.starts_with("**") {
            if let Some(end) = rest[1..].find('*').filter(|&e| e > 0) {
                out.push_str(&format!("<em>{}</em>", inline(&rest[1..1 + end])));
                rest = &rest[end + 2..];
                continue;
            }
        }
        if c == '[' {
            if let Some(close) = rest.find("](") {
                if let Some(end) = rest[close..].find(')') {
                    out.push_str(&inline(&rest[1..close]));
                    rest = &rest[close + end + 1..];
                    continue;
                }
            }
        }
        out.push_str(&escape(&c.to_string()));
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// The cells of a table row `| a | b |` (an escaped `\|` stays in its cell).
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|');
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut cells = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                chars.next();
                if let Some(s) = cells.last_mut() {
                    s.push_str("\\|");
                }
            }
            '|' => cells.push(String::new()),
            c => {
                if let Some(s) = cells.last_mut() {
                    s.push(c);
                }
            }
        }
    }
    cells.into_iter().map(|s| s.trim().to_string()).collect()
}

fn is_separator(line: &str) -> bool {
    let t = line.trim();
    t.starts_with('|') && t.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
}

/// A list item's text when `line` starts one: (`ul`/`ol`, text).
fn list_item(line: &str) -> Option<(&'static str, &str)> {
    let t = line.trim_start();
    if let Some(text) = t.strip_prefix("- ").or_else(|| t.strip_prefix("* ")) {
        return Some(("ul", text));
    }
    let digits = t.chars().take_while(char::is_ascii_digit).count();
    if digits > 0 {
        if let Some(text) = t[digits..].strip_prefix(". ") {
            return Some(("ol", text));
        }
    }
    None
}

/// Renders a document.
pub fn render(md: &str) -> String {
    let lines: Vec<&str> = md.lines().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let t = line.trim();
        if t.is_empty() {
            i += 1;
        } else if t.starts_with("```") {
            let mut code = Vec::new();
            i += 1;
            while i < lines.len() && !lines[i].trim_start().starts_with("```") {
                code.push(lines[i]);
                i += 1;
            }
            i += 1;
            out.push_str(&format!("<pre><code>{}</code></pre>\n", escape(&code.join("\n"))));
        } else if let Some(level) = (1..=6).find(|&n| t.starts_with(&"#".repeat(n)) && t[n..].starts_with(' ')) {
            let text = t[level..].trim();
            out.push_str(&format!("<h{level}>{}</h{level}>\n", inline(text)));
            i += 1;
        } else if t.starts_with('|') {
            out.push_str("<table>\n");
            let mut header = i + 1 < lines.len() && is_separator(lines[i + 1]);
            while i < lines.len() && lines[i].trim().starts_with('|') {
                if !is_separator(lines[i]) {
                    let tag = if header { "th" } else { "td" };
                    out.push_str("<tr>");
                    for c in cells(lines[i]) {
                        out.push_str(&format!("<{tag}>{}</{tag}>", inline(&c)));
                    }
                    out.push_str("</tr>\n");
                } else {
                    header = false;
                }
                i += 1;
            }
            out.push_str("</table>\n");
        } else if let Some((tag, _)) = list_item(line) {
            out.push_str(&format!("<{tag}>\n"));
            while i < lines.len() {
                let Some((_, text)) = list_item(lines[i]) else { break };
                let mut item = text.to_string();
                i += 1;
                // Continuation lines: indented, not a new item.
                while i < lines.len() && lines[i].starts_with("  ") && list_item(lines[i]).is_none() && !lines[i].trim().is_empty() {
                    item.push(' ');
                    item.push_str(lines[i].trim());
                    i += 1;
                }
                out.push_str(&format!("<li>{}</li>\n", inline(&item)));
            }
            out.push_str(&format!("</{tag}>\n"));
        } else {
            let mut para = Vec::new();
            while i < lines.len() {
                let l = lines[i].trim();
                if l.is_empty() || l.starts_with('#') || l.starts_with('|') || l.starts_with("```") || list_item(lines[i]).is_some() {
                    break;
                }
                para.push(l);
                i += 1;
            }
            out.push_str(&format!("<p>{}</p>\n", inline(&para.join(" "))));
        }
    }
    out
}

#[cfg(test)]
mod tests;
