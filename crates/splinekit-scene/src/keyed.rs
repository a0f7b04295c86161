//! Lists keyed by a local piece's index k or a patch's pair (k, l), as the blending
//! splines' `transforms` and `local_control_points` hold them: written as a JSON object
//! whose keys are `"k"` or `"k,l"`, read back from those keys.

use serde::de::DeserializeOwned;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use serde_json::{Map, Value};

use crate::error::{DocumentError, Result};
use crate::json::fields;

/// The index of a local piece as the key of a JSON object: local k as `"k"`, patch (k, l)
/// as `"k,l"`; read with blanks allowed around an index.
pub(crate) trait Key: Sized {
    /// The index a key names, or `None` when it names none.
    fn parse(key: &str) -> Option<Self>;
    /// The key naming this index.
    fn key(&self) -> String;
}

impl Key for usize {
    fn parse(key: &str) -> Option<Self> {
        parse_index(key)
    }
    fn key(&self) -> String {
        self.to_string()
    }
}

impl Key for (usize, usize) {
    /// Two indices separated by a comma.
    fn parse(key: &str) -> Option<Self> {
        key.split_once(',').and_then(|(a, b)| Some((parse_index(a)?, parse_index(b)?)))
    }
    fn key(&self) -> String {
        format!("{},{}", self.0, self.1)
    }
}

/// The index k of a key `"k"` (blanks around it allowed), or `None` when the key is not
/// one index. Every keyed field reads a local's index with it.
pub(crate) fn parse_index(key: &str) -> Option<usize> {
    key.trim().parse().ok()
}

/// Writes `entries` as one JSON object, each value under its index's key, in the list's
/// order: the `serialize` of the keyed fields' `with` modules.
pub(crate) fn serialize<S: Serializer, K: Key, T: Serialize>(
    entries: &[(K, T)],
    serializer: S,
) -> std::result::Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(Some(entries.len()))?;
    for (index, value) in entries {
        map.serialize_entry(&index.key(), value)?;
    }
    map.end()
}

/// Reads the entries of a JSON object keyed by index: each key as a `K` (a key naming none
/// is an error at that key with the message `refusal`), each value as a `T` (errors located
/// inside that key), in the object's order.
pub(crate) fn entries<K: Key, T: DeserializeOwned>(object: Map<String, Value>, refusal: &str) -> Result<Vec<(K, T)>> {
    object
        .into_iter()
        .map(|(key, value)| {
            let k = K::parse(&key).ok_or_else(|| DocumentError::new(key.as_str(), refusal))?;
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
        assert_eq!(<(usize, usize)>::parse("2,3"), Some((2, 3)));
        assert_eq!(<(usize, usize)>::parse(" 2 , 3 "), Some((2, 3)));
        for key in ["2", "2,", ",3", "2;3", "-1,0", "a,b", "1,2,3"] {
            assert_eq!(<(usize, usize)>::parse(key), None, "{key}");
        }
        assert_eq!((2, 3).key(), "2,3");
        assert_eq!(7.key(), "7");
        assert_eq!(usize::parse(" 7"), Some(7));
    }

    #[test]
    fn entries_keep_the_object_order_and_locate_errors() {
        let Value::Object(map) = json!({"3": 1.5, "0": 2.5}) else { unreachable!() };
        let read: Vec<(usize, f64)> = entries(map, "bad key").unwrap();
        assert_eq!(read, vec![(3, 1.5), (0, 2.5)]);

        let Value::Object(map) = json!({"0": 1.0, "x": 2.0}) else { unreachable!() };
        let err = entries::<usize, f64>(map, "keys must be indices").unwrap_err();
        assert_eq!(err.to_string(), "x: keys must be indices");

        let Value::Object(map) = json!({"1,2": "text"}) else { unreachable!() };
        let err = entries::<(usize, usize), f64>(map, "bad key").unwrap_err();
        assert_eq!(err.path, "1,2");
    }

    #[test]
    fn serialize_writes_one_object_in_list_order() {
        let list = vec![((1, 0), 0.5), ((0, 2), 1.5)];
        let value = serialize(&list, serde_json::value::Serializer).unwrap();
        assert_eq!(serde_json::to_string(&value).unwrap(), r#"{"1,0":0.5,"0,2":1.5}"#);
    }
}
