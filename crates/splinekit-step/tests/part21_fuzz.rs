//! Property fuzz of the Part 21 reader (bounded cases; the long coverage-guided runs live
//! in `fuzz/`): arbitrary bytes, and valid files with bytes flipped, cut or spliced, are
//! either read or refused with an error that names a line in the file — never a panic or
//! hang.

use proptest::prelude::*;
use splinekit_step::part21::StepFile;

const VALID: &str = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\n\
FILE_NAME('a','t',(''),(''),'s','s','');\nFILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n\
#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(0.,0.,1.));\n#3=DIRECTION('',(1.,0.,0.));\n\
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);\n#5=CIRCLE('c',#4,2.5);\n\
#6=( BOUNDED_CURVE() B_SPLINE_CURVE(1,(#1,#7),.UNSPECIFIED.,.F.,.F.) \
B_SPLINE_CURVE_WITH_KNOTS((2,2),(0.,1.),.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() \
RATIONAL_B_SPLINE_CURVE((1.,2.)) REPRESENTATION_ITEM('') );\n#7=CARTESIAN_POINT('',(1.,2.,3.));\n\
/* a comment */ #8=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),$,'d','\\X2\\03B1\\X0\\');\n\
ENDSEC;\nEND-ISO-10303-21;\n";

fn check(bytes: Vec<u8>) {
    let lines = bytes.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
    match StepFile::from_bytes(bytes) {
        Ok(f) => {
            for id in f.ids().collect::<Vec<_>>() {
                f.get(id).expect("indexed instances parse again");
            }
        }
        Err(e) => {
            assert!(e.location.line >= 1 && e.location.line <= lines, "line {} of {lines}: {e}", e.location.line);
            assert!(!e.to_string().contains('\n'), "one line: {e}");
        }
    }
}

#[test]
fn the_valid_file_reads() {
    let f = StepFile::from_bytes(VALID.as_bytes().to_vec()).unwrap();
    assert_eq!(f.len(), 8);
    assert_eq!(f.census().iter().map(|(_, c)| c).sum::<usize>(), 8);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        check(bytes);
    }

    #[test]
    fn flipped_bytes(edits in proptest::collection::vec((0usize..2000, any::<u8>()), 1..4)) {
        let mut b = VALID.as_bytes().to_vec();
        for (i, v) in edits {
            let n = b.len();
            b[i % n] = v;
        }
        check(b);
    }

    #[test]
    fn cut_and_spliced(cut in 0usize..2000, from in 0usize..2000, len in 0usize..80) {
        let v = VALID.as_bytes();
        let cut = cut % v.len();
        let from = from % v.len();
        let mut b = v[..cut].to_vec();
        b.extend_from_slice(&v[from..(from + len).min(v.len())]);
        b.extend_from_slice(&v[cut..]);
        check(b);
    }
}
