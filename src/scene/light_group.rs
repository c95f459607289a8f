//! `light_group`: which lights light which objects. Every group gets a number (0 is the
//! scene outside any group); an object inside a group is lit by its group's lights, and by
//! the lights outside every group only with `global_lights on` (manual 3.4.4.2; nesting as
//! povray 3.7.0 draws it, not as the manual says: see `scene::build`).

/// The lights one set of objects sees.
#[derive(Clone, Debug)]
pub struct LightSet {
    /// The group whose lights count (povray 3.7.0: the object's innermost group only); 0 for
    /// objects outside every group.
    pub group: u16,
    /// Whether the lights outside every group count.
    pub global: bool,
}

impl LightSet {
    /// The set of objects outside every group: lit by the lights outside every group.
    pub fn outside() -> LightSet {
        LightSet {
            group: 0,
            global: true,
        }
    }

    /// Whether a light of group `group` lights this set's objects.
    pub fn sees(&self, group: u16) -> bool {
        if group == 0 {
            self.global
        } else {
            group == self.group
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_group_sees_its_own_lights_and_the_global_ones_when_asked() {
        let outer = LightSet {
            group: 1,
            global: false,
        };
        let inner = LightSet {
            group: 2,
            global: true,
        };
        assert!(outer.sees(1) && !outer.sees(2) && !outer.sees(0));
        assert!(!inner.sees(1) && inner.sees(2) && inner.sees(0));
        assert!(LightSet::outside().sees(0) && !LightSet::outside().sees(1));
    }
}
