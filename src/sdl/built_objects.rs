//! Objects that `trace()`, `inside()`, `min_extent()` and `max_extent()` have built from a
//! declared identifier, kept so that a scene calling them in a loop (placing 256 trees on a
//! height field with `trace`) builds each object once instead of on every call.
//!
//! An entry is found by the identifier's name and the symbol table it was read from. It is
//! dropped when anything writes that name (`#declare`, `#local`, a by-reference macro
//! parameter, `#undef`) and when its symbol table goes away (the end of a macro or include
//! file), so a name bound afresh in a later macro call, or shadowed by a `#local`, is never
//! answered with the old object.

use std::rc::Rc;

use rustc_hash::FxHashMap;

use crate::scene::object::Object;

/// A built object: `None` when nothing in it is geometry lancer renders (the caller answers
/// as for an empty object and warns again).
pub(super) type Built = Option<Rc<Object>>;

#[derive(Default)]
pub(super) struct BuiltObjects {
    /// Name -> (index of the symbol table holding it, the object built from its value).
    by_name: FxHashMap<Rc<str>, (usize, Built)>,
    /// Counts the writes and table removals, so a call can tell that none happened between
    /// reading its object argument and looking it up here (a macro called in a later argument
    /// could re-declare the object; the argument then holds the old value).
    generation: u64,
}

/// Where a call's object argument was read from: its name, symbol table and the generation.
pub(super) struct Key {
    pub name: Rc<str>,
    pub scope: usize,
    pub generation: u64,
}

/// How a call got its object argument.
pub(super) enum ObjectArg {
    /// Its description was read (and copied) from this identifier.
    Read(Key),
    /// The identifier's object was kept: its description was not even read.
    Kept(Built),
}

impl BuiltObjects {
    pub(super) fn generation(&self) -> u64 {
        self.generation
    }

    /// The object built from the value `key` was read from, if it is still current.
    pub(super) fn get(&self, key: &Key) -> Option<Built> {
        if key.generation != self.generation {
            return None;
        }
        match self.by_name.get(&key.name) {
            Some((s, b)) if *s == key.scope => Some(b.clone()),
            _ => None,
        }
    }

    /// Keeps what was built from the value `key` was read from, unless that value may have
    /// changed since.
    pub(super) fn insert(&mut self, key: Key, built: Built) {
        if key.generation == self.generation {
            self.by_name.insert(key.name, (key.scope, built));
        }
    }

    /// `name` was written (or removed): whatever was built from it is stale.
    pub(super) fn forget(&mut self, name: &str) {
        self.generation += 1;
        if !self.by_name.is_empty() {
            self.by_name.remove(name);
        }
    }

    /// Only `len` symbol tables are left: entries read from the ones removed are stale (a
    /// later macro call's table gets the same index).
    pub(super) fn scopes_left(&mut self, len: usize) {
        self.generation += 1;
        if !self.by_name.is_empty() {
            self.by_name.retain(|_, (s, _)| *s < len);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_go_with_their_name_or_table() {
        let mut b = BuiltObjects::default();
        let key = |b: &BuiltObjects, name: &str, scope| Key {
            name: name.into(),
            scope,
            generation: b.generation(),
        };
        b.insert(key(&b, "A", 0), None);
        b.insert(key(&b, "B", 2), None);
        assert!(b.get(&key(&b, "A", 0)).is_some());
        assert!(
            b.get(&key(&b, "A", 1)).is_none(),
            "a shadowing table is another binding"
        );
        let old = key(&b, "A", 0);
        b.scopes_left(2);
        assert!(b.get(&key(&b, "B", 2)).is_none());
        assert!(
            b.get(&old).is_none(),
            "read before a write: maybe another value"
        );
        b.insert(old, None);
        assert!(
            b.get(&key(&b, "A", 0)).is_some(),
            "A itself was not written"
        );
        b.forget("A");
        assert!(b.get(&key(&b, "A", 0)).is_none());
    }
}
