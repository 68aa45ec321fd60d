//! A list of at most `M` values on the stack, no heap: the one type behind every fixed-capacity
//! list of inverse kinematics (a call's solutions, a polynomial's roots, subproblems 5's and 6's
//! angle triples and pairs). A push past the capacity is an error its caller must handle (the
//! solvers name the invariant that bounds their count), never an entry dropped.

/// A push past a [`BoundedList`]'s capacity: the value was not stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Full;

impl core::fmt::Display for Full {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the list is full")
    }
}

impl core::error::Error for Full {}

/// At most `M` values of `T`, in the order they were pushed.
///
/// ```
/// use kinematics_core::ik::{BoundedList, Full};
/// let mut roots: BoundedList<f64, 2> = BoundedList::new(0.0);
/// assert_eq!(roots.push(1.5), Ok(()));
/// assert_eq!(roots.push(-0.5), Ok(()));
/// assert_eq!(roots.push(2.0), Err(Full));
/// assert_eq!(roots.as_slice(), [1.5, -0.5]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundedList<T, const M: usize> {
    items: [T; M],
    len: usize,
}

impl<T: Copy, const M: usize> BoundedList<T, M> {
    /// No values (`filler` holds the unused places, never read).
    pub const fn new(filler: T) -> Self {
        BoundedList { items: [filler; M], len: 0 }
    }

    /// The first `len` of `items` (all of them when `len` is more than `M`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(crate) fn from_first(items: [T; M], len: usize) -> Self {
        BoundedList { items, len: if len < M { len } else { M } }
    }

    /// Appends `value`, or returns [`Full`] (and stores nothing) when there are `M` already.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn push(&mut self, value: T) -> Result<(), Full> {
        let slot = self.items.get_mut(self.len).ok_or(Full)?;
        *slot = value;
        self.len += 1;
        Ok(())
    }

    /// The values, in the order pushed.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn as_slice(&self) -> &[T] {
        &self.items[..self.len]
    }

    /// The values, to change in place.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        &mut self.items[..self.len]
    }

    /// How many there are.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are none.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The last value pushed.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn last(&self) -> Option<&T> {
        self.as_slice().last()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_list_refuses_and_keeps_what_it_has() {
        let mut list: BoundedList<u8, 3> = BoundedList::new(0);
        assert!(list.is_empty() && list.last().is_none());
        for x in 1..=3 {
            assert_eq!(list.push(x), Ok(()));
        }
        assert_eq!(list.push(4), Err(Full));
        assert_eq!((list.as_slice(), list.len(), list.last()), (&[1, 2, 3][..], 3, Some(&3)));
        list.as_mut_slice()[0] = 9;
        assert_eq!(list.as_slice(), [9, 2, 3]);
        let none: BoundedList<u8, 0> = BoundedList::new(0);
        assert_eq!({ none }.push(1), Err(Full));
        assert_eq!(BoundedList::from_first([1, 2, 3], 2).as_slice(), [1, 2]);
        assert_eq!(BoundedList::from_first([1, 2, 3], 7).as_slice(), [1, 2, 3]);
    }
}
