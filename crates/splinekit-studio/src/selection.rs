//! What is selected: the object (the Properties panel shows it), the handle picked last
//! (its local's control points are shown; the Properties panel edits it) and every
//! selected handle. Shift+click adds or removes one, a box drawn with Ctrl on empty space
//! selects the handles inside it, A selects every shown handle of the object, Escape
//! clears; moving them together is [`crate::group_move`].
//!
//! Handles are told apart by object and kind; after an edit, an undo or a redo the
//! selection follows them to where the document now has them ([`Selection::follow`]).

use crate::handles::Handle;
use crate::view_camera::Projector;

/// The selected object and handles.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Selection {
    /// The selected object.
    pub object: Option<usize>,
    /// The handle picked last (its local's control points are shown; the Properties panel
    /// edits it).
    pub handle: Option<Handle>,
    /// Every selected handle, in the order they were selected (`handle` among them).
    pub handles: Vec<Handle>,
}

fn same(a: &Handle, b: &Handle) -> bool {
    a.object == b.object && a.kind == b.kind
}

impl Selection {
    /// Whether `h` is selected.
    pub fn contains(&self, h: &Handle) -> bool {
        self.handles.iter().any(|s| same(s, h))
    }

    /// Adds `h`, or removes it when it was selected; `true` when it is now selected.
    pub fn toggle(&mut self, h: Handle) -> bool {
        match self.handles.iter().position(|s| same(s, &h)) {
            Some(i) => {
                self.handles.remove(i);
                false
            }
            None => {
                self.handles.push(h);
                true
            }
        }
    }

    /// Adds the handles not yet selected.
    pub fn extend(&mut self, hs: impl IntoIterator<Item = Handle>) {
        for h in hs {
            if !self.contains(&h) {
                self.handles.push(h);
            }
        }
    }

    /// The mean of the selected handles' positions.
    pub fn centroid(&self) -> Option<[f64; 3]> {
        centroid(&self.handles)
    }

    /// Moves the selected handles (and the one picked last) to where `now` has them;
    /// those gone are dropped.
    pub fn follow(&mut self, now: &[Handle]) {
        self.handles = self.handles.iter().filter_map(|h| now.iter().find(|n| same(n, h)).cloned()).collect();
        self.handle = self.handle.as_ref().and_then(|h| now.iter().find(|n| same(n, h)).cloned());
    }

    /// Selects no handle (the object stays selected).
    pub fn clear_handles(&mut self) {
        self.handle = None;
        self.handles.clear();
    }

    /// Selects object `object` of `count` (none: `None`; an index past the end selects
    /// none) and no handle.
    pub fn select_object(&mut self, object: Option<usize>, count: usize) {
        self.object = object.filter(|&i| i < count);
        self.clear_handles();
    }

    /// Selects `h` alone, and its object.
    pub fn select_only(&mut self, h: Handle) {
        self.object = Some(h.object);
        self.handles = vec![h.clone()];
        self.handle = Some(h);
    }

    /// A click on `picked` (none: empty space): selects it alone, or with `add` (Shift)
    /// adds it to the selection or removes it. A click on empty space without `add`
    /// clears the handles.
    pub fn click(&mut self, picked: Option<Handle>, add: bool) {
        match (picked, add) {
            (Some(h), true) => {
                self.object = Some(h.object);
                self.handle = if self.toggle(h.clone()) { Some(h) } else { self.handles.last().cloned() };
            }
            (Some(h), false) => self.select_only(h),
            (None, true) => {}
            (None, false) => self.clear_handles(),
        }
    }

    /// Selects `inside` (the handles in a box), with `add` in addition to the selection;
    /// the last of them becomes the picked handle and its object the selected one.
    pub fn select_box(&mut self, inside: Vec<Handle>, add: bool) {
        if !add {
            self.handles.clear();
        }
        self.extend(inside);
        self.handle = self.handles.last().cloned();
        if let Some(h) = &self.handle {
            self.object = Some(h.object);
        }
    }

    /// Adds `all` (every shown handle of the object); the last becomes the picked handle
    /// when none was.
    pub fn add_all(&mut self, all: Vec<Handle>) {
        self.extend(all);
        if self.handle.is_none() {
            self.handle = self.handles.last().cloned();
        }
    }

    /// The selected handles (the selection, else the one picked last).
    pub fn selected_handles(&self) -> Vec<Handle> {
        if self.handles.is_empty() { self.handle.iter().cloned().collect() } else { self.handles.clone() }
    }
}

/// The mean of the handles' positions (`None` for none).
pub fn centroid(handles: &[Handle]) -> Option<[f64; 3]> {
    if handles.is_empty() {
        return None;
    }
    let n = handles.len() as f64;
    Some([0, 1, 2].map(|i| handles.iter().map(|h| h.position[i]).sum::<f64>() / n))
}

/// The handles whose projection lies in the box with corners `a` and `b` (view pixels).
pub fn in_box<'a>(
    handles: impl IntoIterator<Item = &'a Handle>,
    projector: &Projector,
    a: [f64; 2],
    b: [f64; 2],
) -> Vec<Handle> {
    let (lo, hi) = ([a[0].min(b[0]), a[1].min(b[1])], [a[0].max(b[0]), a[1].max(b[1])]);
    handles
        .into_iter()
        .filter(|h| {
            projector
                .project(h.position)
                .is_some_and(|(p, _)| (lo[0]..=hi[0]).contains(&p[0]) && (lo[1]..=hi[1]).contains(&p[1]))
        })
        .cloned()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::handles::HandleKind;

    fn h(i: usize) -> Handle {
        Handle {
            object: 0,
            kind: HandleKind::ControlPoint(i, "control_points"),
            position: [i as f64, 0.0, 0.0],
            origin: [i as f64, 0.0, 0.0],
            dimension: 2,
            pivot: None,
        }
    }

    #[test]
    fn toggling_adds_and_removes() {
        let mut s = Selection::default();
        assert!(s.toggle(h(0)));
        assert!(s.toggle(h(2)));
        assert_eq!(s.centroid(), Some([1.0, 0.0, 0.0]));
        assert!(!s.toggle(h(0)));
        assert_eq!(s.handles, [h(2)]);
        s.extend([h(2), h(3)]);
        assert_eq!(s.handles.len(), 2);
        s.follow(&[h(3)]);
        assert_eq!(s.handles, [h(3)]);
    }

    /// Shift+click on a selected handle removes it and picks the last one left; a plain
    /// click selects one alone; following a document without the picked handle lets it go.
    #[test]
    fn clicks_pick_and_following_lets_go() {
        let mut s = Selection::default();
        s.click(Some(h(1)), false);
        s.click(Some(h(4)), true);
        s.click(Some(h(5)), true);
        assert_eq!((s.handles.len(), s.handle.clone()), (3, Some(h(5))));
        s.click(Some(h(5)), true);
        assert_eq!((s.handles.len(), s.handle.clone(), s.object), (2, Some(h(4)), Some(0)));
        s.follow(&[h(1)]);
        assert_eq!((s.handles.clone(), s.handle.clone()), (vec![h(1)], None));
        assert_eq!(s.selected_handles(), [h(1)]);
        s.click(None, false);
        assert_eq!((s.handles.len(), s.handle.clone(), s.object), (0, None, Some(0)));
        s.select_object(Some(3), 2);
        assert_eq!(s.object, None, "an index past the end selects none");
    }
}
