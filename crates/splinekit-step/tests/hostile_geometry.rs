//! Geometry that parses as Part 21 but makes no sense — degrees past the knots, knot
//! multiplicities of 10¹⁵, one-coordinate vertices, truncated records, weight lists of the
//! wrong length — is refused by the importer with an error naming the entity's line, never
//! a panic or an allocation the machine cannot hold.

use proptest::prelude::*;
use splinekit_step::import::import;
use splinekit_step::part21::StepFile;

/// A file whose DATA section is `data`, its instances gathered in a geometric set #100.
fn file(data: &str, roots: &str) -> String {
    format!(
        "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n\
         FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n\
         #1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=CARTESIAN_POINT('',(1.,0.,0.));\n\
         #3=CARTESIAN_POINT('',(1.,1.,0.));\n#4=CARTESIAN_POINT('',(0.,1.,0.));\n\
         {data}\n#100=GEOMETRIC_SET('',({roots}));\nENDSEC;\nEND-ISO-10303-21;\n"
    )
}

/// Reads and imports `text`: an import or an error on one line, never a panic.
fn outcome(text: &str) -> Result<usize, String> {
    let f = StepFile::from_bytes(text.as_bytes().to_vec()).map_err(|e| e.to_string())?;
    match import(&f) {
        Ok(imported) => Ok(imported.geometry.len()),
        Err(e) => {
            let message = e.to_string();
            assert!(!message.contains('\n'), "one line: {message}");
            Err(message)
        }
    }
}

fn refused(data: &str, roots: &str, says: &str) {
    match outcome(&file(data, roots)) {
        Err(message) => assert!(message.contains(says), "expected '{says}' in: {message}"),
        Ok(n) => panic!("imported {n} items from a file that should be refused ({says})"),
    }
}

#[test]
fn a_degree_past_the_knots_is_refused() {
    refused(
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',7,(#1,#2,#3),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);",
        "#10",
        "need 11 knots",
    );
}

#[test]
fn knot_multiplicities_of_ten_to_the_fifteenth_are_refused_before_they_are_expanded() {
    refused(
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(1000000000000000,2),(0.,1.),.UNSPECIFIED.);",
        "#10",
        "the multiplicities give 1000000000000002",
    );
    refused(
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(18446744073709551615,2),(0.,1.),.UNSPECIFIED.);",
        "#10",
        "",
    );
}

#[test]
fn a_degree_zero_curve_and_mismatched_knot_lists_are_refused() {
    refused(
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',0,(#1,#2),.UNSPECIFIED.,.F.,.F.,(1,1,1),(0.,1.,2.),.UNSPECIFIED.);",
        "#10",
        "degree must be 1 to 1024",
    );
    refused(
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.,2.),.UNSPECIFIED.);",
        "#10",
        "3 knot values but 2 multiplicities",
    );
}

#[test]
fn truncated_spline_records_are_refused() {
    refused("#10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2));", "#10", "missing parameters");
    refused("#10=B_SPLINE_SURFACE_WITH_KNOTS('',1,1);", "#10", "missing parameters");
}

#[test]
fn rational_weights_of_the_wrong_length_are_refused() {
    refused(
        "#10=( BOUNDED_CURVE() B_SPLINE_CURVE(1,(#1,#2),.UNSPECIFIED.,.F.,.F.) \
         B_SPLINE_CURVE_WITH_KNOTS((2,2),(0.,1.),.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() \
         RATIONAL_B_SPLINE_CURVE((1.,2.,3.)) REPRESENTATION_ITEM('') );",
        "#10",
        "3 weights for 2 control points",
    );
}

#[test]
fn a_ragged_control_net_is_refused() {
    refused(
        "#10=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#1,#2),(#3)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.);",
        "#10",
        "row 1 of the control net has 1 points, row 0 has 2",
    );
}

#[test]
fn a_one_coordinate_point_is_read_as_a_point_on_the_x_axis() {
    let data = "#9=CARTESIAN_POINT('',(2.));\n\
                #10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#9),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);";
    assert_eq!(outcome(&file(data, "#10")), Ok(1));
}

#[test]
fn the_valid_spline_still_imports() {
    let data = "#10=B_SPLINE_CURVE_WITH_KNOTS('',2,(#1,#2,#3,#4),.UNSPECIFIED.,.F.,.F.,(3,1,3),(0.,0.5,1.),.UNSPECIFIED.);\n\
                #11=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#1,#2),(#4,#3)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.);";
    assert_eq!(outcome(&file(data, "#10,#11")), Ok(2));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    /// Any degree, multiplicities and control-point count: imported or refused, never a
    /// panic, and never with more knots than the points ask for.
    #[test]
    fn any_spline_header_is_imported_or_refused(
        degree in 0u64..12,
        mults in proptest::collection::vec(0u64..6, 0..6),
        points in 0usize..5,
        surface in any::<bool>(),
    ) {
        let values: Vec<String> = (0..mults.len()).map(|i| format!("{i}.")).collect();
        let mults: Vec<String> = mults.iter().map(u64::to_string).collect();
        let pts: Vec<&str> = ["#1", "#2", "#3", "#4"].iter().cycle().take(points).copied().collect();
        let (m, v) = (mults.join(","), values.join(","));
        let data = if surface {
            format!(
                "#10=B_SPLINE_SURFACE_WITH_KNOTS('',{degree},1,(({}),({})),.UNSPECIFIED.,.F.,.F.,.F.,({m}),(2,2),({v}),(0.,1.),.UNSPECIFIED.);",
                pts.join(","),
                pts.join(",")
            )
        } else {
            format!("#10=B_SPLINE_CURVE_WITH_KNOTS('',{degree},({}),.UNSPECIFIED.,.F.,.F.,({m}),({v}),.UNSPECIFIED.);", pts.join(","))
        };
        let _ = outcome(&file(&data, "#10"));
    }
}
