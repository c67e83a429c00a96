use super::*;

#[test]
fn renders_the_register_forms() {
    let md = "# Title\n\nSome **bold** and *it* and `a<b`, a [link](x.md).\nSecond line.\n\n- one\n  more\n- two\n\n1. first\n\n| a | b |\n|---|---|\n| \\|x\\| | <y> |\n";
    let html = render(md);
    assert!(html.contains("<h1>Title</h1>"), "{html}");
    assert!(html.contains("<p>Some <strong>bold</strong> and <em>it</em> and <code>a&lt;b</code>, a link. Second line.</p>"), "{html}");
    assert!(html.contains("<ul>\n<li>one more</li>\n<li>two</li>\n</ul>"), "{html}");
    assert!(html.contains("<ol>\n<li>first</li>\n</ol>"), "{html}");
    assert!(html.contains("<tr><th>a</th><th>b</th></tr>"), "{html}");
    assert!(html.contains("<tr><td>|x|</td><td>&lt;y&gt;</td></tr>"), "{html}");
}

#[test]
fn the_register_renders_without_raw_markup() {
    let html = render(include_str!("../../../../docs/INTERPRETATION.md"));
    assert!(html.contains("<h1>Interpretation register</h1>"));
    assert!(!html.contains("<script"));
    assert!(html.matches("<table>").count() >= 1);
}
