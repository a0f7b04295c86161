//! Lists keyed by a local piece's index k or a patch's pair (k, l), as the blending
//! splines' `transforms` and `local_control_points` hold them: written as a JSON object
//! whose keys are `"k"` or `"k,l"`, read back from those keys.

use serde::de::DeserializeOwned;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use serde_json::{Map, Value};

use crate::error::{DocumentError, Result};
use crate::json::fields;

/// The pair (k, l) of a key `"k,l"` (blanks around either index allowed), or `None` when
/// the key is not two indices separated by a comma.
pub(crate) fn parse_pair(key: &str) -> Option<(usize, usize)> {
    key.split_once(',').and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)))
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
