//! Edits of a scene document as commands: each replaces one JSON value inside one object
//! (`/shape/transforms/3`, `/shape/control_points/2`, `/density`, …), adds or removes an
//! object. An edit is applied only when the edited object still parses *and* builds, so the
//! document never becomes invalid; otherwise the library's own message comes back, naming
//! the field as on the command line.

use serde_json::Value;
use splinekit_scene::scenes::{SceneDocument, SceneObject};
use splinekit_scene::{DocumentError, ShapeDocument};

/// One change of a scene document.
#[derive(Debug, Clone, PartialEq)]
pub enum Edit {
    /// Sets the value at the JSON `pointer` (RFC 6901) of object `object`'s document
    /// (`{"shape": {…}, …style…}`), creating missing parent objects; `None` removes it.
    Set {
        /// Index of the object.
        object: usize,
        /// Where in the object's document.
        pointer: String,
        /// The new value (`None`: remove the field).
        value: Option<Value>,
    },
    /// Inserts an object at `index`.
    Insert {
        /// Where in the object list.
        index: usize,
        /// The object.
        object: Box<SceneObject>,
    },
    /// Removes the object at `index`.
    Remove {
        /// Which object.
        index: usize,
    },
    /// Several edits as one (a selection moved together): applied in order, all or none.
    Batch(Vec<Edit>),
}

/// Why an edit was refused (the document is unchanged).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EditError {
    /// The edited document is not valid: the library's message.
    #[error("{0}")]
    Invalid(#[from] DocumentError),
    /// The edit names something that does not exist.
    #[error("{0}")]
    Missing(String),
}

/// Checks that an edited object's shape builds: given the object's index and its shape.
pub type BuildCheck<'a> = dyn FnMut(usize, &ShapeDocument) -> Result<(), DocumentError> + 'a;

impl Edit {
    /// Applies the edit, returning the edit that undoes it.
    pub fn apply(&self, scene: &mut SceneDocument) -> Result<Edit, EditError> {
        self.apply_with(scene, &mut |_, shape| check_builds(shape))
    }

    /// [`Self::apply`], with `check` building the edited shape (the studio's, which keeps
    /// what it built, [`crate::live_surfaces::LiveSurfaces::check_build`]; it must refuse
    /// what [`check_builds`] refuses).
    pub fn apply_with(&self, scene: &mut SceneDocument, check: &mut BuildCheck<'_>) -> Result<Edit, EditError> {
        match self {
            Edit::Set { object, pointer, value } => {
                let obj = scene.objects.get(*object).ok_or_else(|| missing_object(*object, scene))?;
                let mut doc = obj.to_value();
                let old = doc.pointer(pointer).cloned();
                set_pointer(&mut doc, pointer, value.clone())?;
                let edited = SceneObject::from_value(doc).map_err(|e| e.within(&format!("objects[{object}]")))?;
                check(*object, &edited.shape).map_err(|e| e.within(&format!("objects[{object}].shape")))?;
                scene.objects[*object] = edited;
                Ok(Edit::Set { object: *object, pointer: pointer.clone(), value: old })
            }
            Edit::Insert { index, object } => {
                if *index > scene.objects.len() {
                    return Err(missing_object(*index, scene));
                }
                scene.objects.insert(*index, (**object).clone());
                Ok(Edit::Remove { index: *index })
            }
            Edit::Remove { index } => {
                if *index >= scene.objects.len() {
                    return Err(missing_object(*index, scene));
                }
                if scene.objects.len() == 1 {
                    return Err(EditError::Invalid(DocumentError::new("objects", "a scene needs at least one object")));
                }
                let object = Box::new(scene.objects.remove(*index));
                Ok(Edit::Insert { index: *index, object })
            }
            Edit::Batch(edits) => {
                let mut undos: Vec<Edit> = Vec::with_capacity(edits.len());
                for e in edits {
                    match e.apply_with(scene, check) {
                        Ok(undo) => undos.push(undo),
                        Err(err) => {
                            // Back to where the batch started: each undo restores a state
                            // that was valid.
                            for u in undos.iter().rev() {
                                u.apply(scene).ok();
                            }
                            return Err(err);
                        }
                    }
                }
                undos.reverse();
                Ok(Edit::Batch(undos))
            }
        }
    }

    /// Whether this edit and `other` change the same value (a drag is one edit).
    pub fn same_target(&self, other: &Edit) -> bool {
        match (self, other) {
            (Edit::Set { object: a, pointer: p, .. }, Edit::Set { object: b, pointer: q, .. }) => a == b && p == q,
            (Edit::Batch(x), Edit::Batch(y)) => x.len() == y.len() && x.iter().zip(y).all(|(a, b)| a.same_target(b)),
            _ => false,
        }
    }
}

fn missing_object(index: usize, scene: &SceneDocument) -> EditError {
    EditError::Missing(format!("objects[{index}]: there are {} objects", scene.objects.len()))
}

/// Builds the shape as a renderer would, so that a value only the kernel checks (a degree
/// above the number of points minus one, an empty knot span) is refused here.
pub fn check_builds(shape: &ShapeDocument) -> Result<(), DocumentError> {
    match shape {
        ShapeDocument::Curve(c) => c.build().map(|_| ()),
        ShapeDocument::Surface(s) => s.build().map(|_| ()),
    }
}

/// Sets (or with `None` removes) the value at an RFC 6901 pointer, creating missing
/// objects on the way; array indices must exist (or be one past the end to append).
pub fn set_pointer(doc: &mut Value, pointer: &str, value: Option<Value>) -> Result<(), EditError> {
    let bad = || EditError::Missing(format!("{pointer}: no such place in the document"));
    let tokens: Vec<String> = pointer.split('/').skip(1).map(|t| t.replace("~1", "/").replace("~0", "~")).collect();
    let Some((last, parents)) = tokens.split_last() else {
        return Err(bad());
    };
    let mut here = doc;
    for t in parents {
        here = match here {
            Value::Object(m) => m.entry(t.clone()).or_insert_with(|| Value::Object(Default::default())),
            Value::Array(a) => t.parse::<usize>().ok().and_then(|i| a.get_mut(i)).ok_or_else(bad)?,
            _ => return Err(bad()),
        };
    }
    match (here, value) {
        (Value::Object(m), Some(v)) => {
            m.insert(last.clone(), v);
        }
        (Value::Object(m), None) => {
            m.remove(last);
        }
        (Value::Array(a), Some(v)) => {
            let i: usize = last.parse().map_err(|_| bad())?;
            match i.cmp(&a.len()) {
                std::cmp::Ordering::Less => a[i] = v,
                std::cmp::Ordering::Equal => a.push(v),
                std::cmp::Ordering::Greater => return Err(bad()),
            }
        }
        (Value::Array(a), None) => {
            let i: usize = last.parse().map_err(|_| bad())?;
            if i >= a.len() {
                return Err(bad());
            }
            a.remove(i);
        }
        _ => return Err(bad()),
    }
    Ok(())
}
