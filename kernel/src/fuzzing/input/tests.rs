use super::*;

#[test]
fn empty_input_is_the_plain_multipass_program() {
    let i = CycleInput::from_bytes(&[]);
    assert_eq!(i, CycleInput::Built { generator: Generator::Multipass, knobs: vec![0; KNOBS], readings: 0 });
    let c = i.case();
    assert_eq!(c.family, "g76");
    assert!(c.text().contains("G76"), "{}", c.text());
}

#[test]
fn bytes_pick_family_and_knobs() {
    let CycleInput::Built { generator, knobs, .. } = CycleInput::from_bytes(&[7, 9, 0, 0, 0]) else { panic!() };
    assert_eq!(generator, family("g92"));
    assert_ne!(knobs[0], 0);
    assert!(knobs[1..].iter().all(|&k| k == 0));
}

#[test]
fn literal_programs_keep_their_configuration() {
    let inch_fanuc = literal_config(3);
    assert_eq!((inch_fanuc.dialect, inch_fanuc.grid.units), (Dialect::Fanuc, Units::Inch));
    let bytes = CycleInput::literal_bytes(b"G0 X1 Z1\n", &inch_fanuc);
    let c = CycleInput::from_bytes(&bytes).case();
    assert_eq!((c.family, c.program.as_slice(), c.config), ("literal", &b"G0 X1 Z1\n"[..], inch_fanuc));
    assert_eq!(literal_bits(&literal_config(6)), 6);
}

#[test]
fn nc201_and_its_families_are_reachable() {
    let radius = literal_config(8 | 16 | 1);
    assert_eq!((radius.dialect, radius.params.x_radius), (Dialect::Nc201, Some(1)));
    assert_eq!(literal_bits(&radius), 8 | 16);
    for (byte, family) in [(16, "g162"), (17, "g162"), (18, "g32"), (19, "g32")] {
        let case = CycleInput::from_bytes(&[byte]).case();
        assert_eq!(case.family, family, "first byte {byte}");
    }
    assert_eq!(CycleInput::from_bytes(&[16]).case().config.dialect, Dialect::Nc201);
}

/// Every registry family has a first byte: the first 20 bytes' families (the multipass
/// byte's first knob choosing among three), then one byte each.
#[test]
fn every_family_is_reachable() {
    let count = FIRST_BYTES + u8::try_from(added_families().len()).unwrap();
    let mut built = std::collections::BTreeSet::new();
    for byte in 0..count {
        if let CycleInput::Built { generator, .. } = CycleInput::from_bytes(&[byte]) {
            for first_knob in [0, 60, 90] {
                built.insert(gen::build(generator.builder(), &[first_knob]).family);
            }
        }
    }
    for f in FAMILIES {
        assert!(built.contains(f.name), "no first byte builds {}: {built:?}", f.name);
    }
    // The byte after the families builds a thread case with an operator script; past it the
    // bytes wrap around to 0.
    let CycleInput::Built { generator, knobs, .. } = CycleInput::from_bytes(&[count, 0, 0, 0, 0]) else { panic!() };
    assert_eq!(generator, Generator::Operator);
    let scripted = (0..40u32).filter(|&k| !gen::build(generator.builder(), &[k, 0, 0, 0]).config.operator.is_empty()).count();
    assert!(scripted > 0 && knobs.len() == KNOBS, "{scripted}");
    assert_eq!(CycleInput::from_bytes(&[count + 1]), CycleInput::from_bytes(&[0]));
}

/// The readings byte: after a built input's knobs, after a literal's configuration byte
/// with bit 5; without it (every input written before the readings) the letter.
#[test]
fn a_readings_byte_chooses_the_readings() {
    let short = [7u8, 9, 0, 0, 0];
    assert!(CycleInput::from_bytes(&short).case().config.readings.is_letter());
    let mut full = vec![7u8];
    full.extend(std::iter::repeat_n(0u8, 4 * KNOBS));
    assert!(CycleInput::from_bytes(&full).case().config.readings.is_letter());
    full.push(0b10_0001);
    let r = CycleInput::from_bytes(&full).case().config.readings;
    assert_eq!(crate::readings::line(&r), "g94.k=start-minus-end, g96.rapid=allow, others the letter");
    let config = Config { readings: crate::readings::from_bits(0b100), ..literal_config(1) };
    let bytes = CycleInput::literal_bytes(b"G0 X1\n", &config);
    assert_eq!(bytes[1] & READINGS_FOLLOW, READINGS_FOLLOW);
    assert_eq!(CycleInput::from_bytes(&bytes).case().config, config);
    let plain = CycleInput::literal_bytes(b"G0 X1\n", &literal_config(1));
    assert_eq!((plain.len(), CycleInput::from_bytes(&plain).case().config), (2 + 6, literal_config(1)));
}
