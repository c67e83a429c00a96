use super::*;
use cycle_vocab::Config;

fn written(t: &Trace, form: Form) -> String {
    let mut bytes = Vec::new();
    let mut w = TraceWriter::start(&mut bytes, form, t.grid);
    for e in &t.events {
        w.event(e);
    }
    w.finish(t.alarm.as_ref()).unwrap();
    String::from_utf8(bytes).unwrap()
}

/// Streamed, both forms are exactly what the whole trace prints.
#[test]
fn streamed_forms_equal_the_whole_trace() {
    for program in ["G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n", "G0 X80 Z10\nG78 P050060 Q0 R0\n", "", "G0 X1\n"] {
        let t = cycle_spec::expand(program.as_bytes(), &Config::default());
        assert_eq!(written(&t, Form::Gcode), t.to_gcode(), "{program}");
        assert_eq!(written(&t, Form::Json), format!("{}\n", t.to_json()), "{program}");
    }
}
