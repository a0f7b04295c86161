//! Lists keyed by a local piece's index k or a patch's pair (k, l), as the blending
//! splines' `transforms` and `local_control_points` hold them: written as a JSON object
//! whose keys are `"k"` or `"k,l"`, read back from those keys.

use serde::de::DeserializeOwned;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use serde_json::{Map, Value};

use crate::error::{DocumentError, Result};
use crate::json::fields;

/// The index k of a key `"k"` (blanks around it allowed), or `None` when the key is not
/// one index. Every keyed field reads a local's index with it.
pub(crate) fn parse_index(key: &str) -> Option<usize> {
    key.trim().parse().ok()
}

/// The pair (k, l) of a key `"k,l"` (blanks around either index allowed), or `None` when
/// the key is not two indices separated by a comma.
pub(crate) fn parse_pair(key: &str) -> Option<(usize, usize)> {
    key.split_once(',').and_then(|(a, b)| Some((parse_index(a)?, parse_index(b)?)))
}

/// The key `"k"` of local k.
pub(crate) fn index_key(k: &usize) -> String {
    k.to_string()
}

/// The key `"k,l"` of patch (k, l).
pub(crate) fn pair_key((k, l): &(usize, usize)) -> String {
    format!("{k},{l}")
}

/// Writes `entries` as one JSON object, each value under the key `key` gives its index,
/// in the list's order.
pub(crate) fn serialize<S: Serializer, K, T: Serialize>(
    entries: &[(K, T)],
    key: impl Fn(&K) -> String,
    serializer: S,
) -> std::result::Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(Some(entries.len()))?;
    for (index, value) in entries {
        map.serialize_entry(&key(index), value)?;
    }
    map.end()
}

/// Reads the entries of a JSON object keyed by index: each key through `index` (a key it
/// refuses is an error at that key with the message `refusal`), each value as a `T`
/// (errors located inside that key), in the object's order.
pub(crate) fn entries<K, T: DeserializeOwned>(
    object: Map<String, Value>,
    index: impl Fn(&str) -> Option<K>,
    refusal: &str,
) -> Result<Vec<(K, T)>> {
    object
        .into_iter()
        .map(|(key, value)| {
            let k = index(&key).ok_or_else(|| DocumentError::new(key.as_str(), refusal))?;
            Ok((k, fields(value).map_err(|e| e.within(&key))?))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    #[test]
    fn index_keys_parse_one_index_and_refuse_the_rest() {
        assert_eq!(parse_index("3"), Some(3));
        assert_eq!(parse_index(" 3 "), Some(3));
        for key in ["", "-1", "a", "3,", "1.5"] {
            assert_eq!(parse_index(key), None, "{key}");
        }
    }

    #[test]
    fn pair_keys_parse_two_indices_and_refuse_the_rest() {
        assert_eq!(parse_pair("2,3"), Some((2, 3)));
        assert_eq!(parse_pair(" 2 , 3 "), Some((2, 3)));
        for key in ["2", "2,", ",3", "2;3", "-1,0", "a,b", "1,2,3"] {
            assert_eq!(parse_pair(key), None, "{key}");
        }
        assert_eq!(pair_key(&(2, 3)), "2,3");
        assert_eq!(index_key(&7), "7");
    }

    #[test]
    fn entries_keep_the_object_order_and_locate_errors() {
        let Value::Object(map) = json!({"3": 1.5, "0": 2.5}) else { unreachable!() };
        let read: Vec<(usize, f64)> = entries(map, parse_index, "bad key").unwrap();
        assert_eq!(read, vec![(3, 1.5), (0, 2.5)]);

        let Value::Object(map) = json!({"0": 1.0, "x": 2.0}) else { unreachable!() };
        let err = entries::<usize, f64>(map, |k| k.parse().ok(), "keys must be indices").unwrap_err();
        assert_eq!(err.to_string(), "x: keys must be indices");

        let Value::Object(map) = json!({"1,2": "text"}) else { unreachable!() };
        let err = entries::<(usize, usize), f64>(map, parse_pair, "bad key").unwrap_err();
        assert_eq!(err.path, "1,2");
    }

    #[test]
    fn serialize_writes_one_object_in_list_order() {
        let list = vec![((1, 0), 0.5), ((0, 2), 1.5)];
        let value = serialize(&list, pair_key, serde_json::value::Serializer).unwrap();
        assert_eq!(serde_json::to_string(&value).unwrap(), r#"{"1,0":0.5,"0,2":1.5}"#);
    }
}
