//! The XML of a map as a small tree: each element's name, attributes (entities
//! resolved), child elements, text and where it starts in the file. Read by `quick-xml`'s
//! streaming reader, the attributes of each start tag split here, into flat arrays (no
//! allocation per element): the reader needs a tree, the messages need positions, and a
//! CARLA town is read several times faster this way than through a general-purpose
//! document model.

use quick_xml::events::{BytesStart, Event};
use std::borrow::Cow;

/// A parsed document: its elements in document order, the first one the root.
pub(crate) struct Tree<'a> {
    elements: Vec<Element>,
    /// Every element's attributes, each element's a contiguous run.
    attributes: Vec<(&'a str, Cow<'a, str>)>,
    /// Text inside elements.
    texts: Vec<Cow<'a, str>>,
    /// Every element's name (without a namespace prefix).
    names: Vec<&'a str>,
}

/// One element: indexes into the tree's arrays (its name is `names` at its own index).
struct Element {
    attributes: (u32, u32),
    first_child: u32,
    next_sibling: u32,
    text: u32,
    start: usize,
}

/// No element (or no text) at this index.
const NONE: u32 = u32::MAX;

/// Why a text is not a tree, and the byte offset where that shows.
#[derive(Debug)]
pub(crate) struct XmlError {
    /// Byte offset into the text.
    pub offset: usize,
    /// What is wrong.
    pub message: String,
}

/// `part` as the same bytes of `text` (the reader hands out slices of the text it reads,
/// borrowed for the event only); `None` when `part` is not inside `text` or not UTF-8 there.
fn within<'a>(text: &'a str, part: &[u8]) -> Option<&'a str> {
    let offset = (part.as_ptr() as usize).checked_sub(text.as_ptr() as usize)?;
    text.get(offset..offset.checked_add(part.len())?)
}

/// Whether two attribute names are the same: most names differ in their length or their
/// first byte (`a`, `b`, `c`, `d`), which is tested before the whole names are.
fn same_name(a: &str, b: &str) -> bool {
    a.len() == b.len() && a.as_bytes().first() == b.as_bytes().first() && a == b
}

/// An element of a [`Tree`].
#[derive(Clone, Copy)]
pub(crate) struct Node<'t, 'a> {
    tree: &'t Tree<'a>,
    index: u32,
}

/// The attributes of a start tag, from the text after its name: name, raw value and
/// whether the value holds an entity reference, or why the tag is malformed there (a name
/// without `=` and a quoted value, a value holding `<`, two attributes without space
/// between them); nothing after an error.
struct Attributes<'a>(&'a str);

impl<'a> Iterator for Attributes<'a> {
    type Item = Result<(&'a str, &'a str, bool), String>;

    fn next(&mut self) -> Option<Self::Item> {
        let (text, bytes) = (self.0, self.0.as_bytes());
        let skip = |mut at: usize| {
            while at < bytes.len() && bytes[at].is_ascii_whitespace() {
                at += 1;
            }
            at
        };
        let start = skip(0);
        if start == bytes.len() {
            return None;
        }
        self.0 = "";
        let malformed = |what: &str| {
            let near: String = text[start..].chars().take(20).collect();
            Some(Err(format!("{what} at '{near}'")))
        };
        if start == 0 {
            return malformed("no space before an attribute");
        }
        let mut end = start;
        while end < bytes.len() && !bytes[end].is_ascii_whitespace() && bytes[end] != b'=' {
            end += 1;
        }
        let equals = skip(end);
        if end == start || equals == bytes.len() || bytes[equals] != b'=' {
            return malformed("an attribute without a value");
        }
        let open = skip(equals + 1);
        let quote = match bytes.get(open) {
            Some(&q) if q == b'"' || q == b'\'' => q,
            _ => return malformed("an attribute value without quotes"),
        };
        let (mut close, mut entity) = (open + 1, false);
        loop {
            match memchr::memchr3(quote, b'<', b'&', &bytes[close..]).map(|n| close + n) {
                Some(at) if bytes[at] == quote => break close = at,
                Some(at) if bytes[at] == b'&' => (close, entity) = (at + 1, true),
                Some(_) => return malformed("'<' in an attribute value"),
                None => return malformed("an attribute value without its closing quote"),
            }
        }
        // Every index here is at an ASCII byte (or the end), so the slices are whole UTF-8.
        self.0 = &text[close + 1..];
        Some(Ok((&text[start..end], &text[open + 1..close], entity)))
    }
}

impl<'a> Tree<'a> {
    /// Parses `text`; refused: text that is not well-formed XML or holds no element.
    pub fn parse(text: &'a str) -> Result<Tree<'a>, XmlError> {
        let mut reader = quick_xml::Reader::from_str(text);
        reader.config_mut().check_end_names = true;
        // Room for what maps hold (about one element per 100 bytes, three attributes each).
        let elements = text.len() / 100;
        let mut tree = Tree {
            elements: Vec::with_capacity(elements),
            attributes: Vec::with_capacity(3 * elements),
            texts: Vec::new(),
            names: Vec::with_capacity(elements),
        };
        // The open elements, and the last child of each so far.
        let mut open: Vec<(u32, u32)> = Vec::new();
        loop {
            let start = reader.buffer_position() as usize;
            let event = reader
                .read_event()
                .map_err(|e| XmlError { offset: reader.error_position() as usize, message: e.to_string() })?;
            let (element, empty) = match event {
                Event::Start(e) => (e, false),
                Event::Empty(e) => (e, true),
                Event::End(_) => {
                    open.pop();
                    continue;
                }
                Event::Text(t) => {
                    // The indentation between elements is no one's text (tested without an
                    // early exit, which the compiler turns into a vector loop).
                    if t.iter().fold(true, |blank, b| blank & b.is_ascii_whitespace()) {
                        continue;
                    }
                    if let Some(&(parent, _)) = open.last() {
                        let text = t.decode().map_err(|e| XmlError { offset: start, message: e.to_string() })?;
                        tree.add_text(parent, text);
                    }
                    continue;
                }
                Event::CData(t) => {
                    if let Some(&(parent, _)) = open.last() {
                        let text = t.decode().map_err(|e| XmlError { offset: start, message: e.to_string() })?;
                        tree.add_text(parent, text);
                    }
                    continue;
                }
                Event::GeneralRef(r) => {
                    let refuse = |message: String| XmlError { offset: start, message };
                    let name = r.decode().map_err(|e| refuse(e.to_string()))?;
                    let text = match r.resolve_char_ref().map_err(|e| refuse(e.to_string()))? {
                        Some(c) => Cow::Owned(c.to_string()),
                        None => Cow::Borrowed(
                            quick_xml::escape::resolve_predefined_entity(&name)
                                .ok_or_else(|| refuse(format!("unknown entity &{name};")))?,
                        ),
                    };
                    if let Some(&(parent, _)) = open.last() {
                        tree.add_text(parent, text);
                    }
                    continue;
                }
                Event::Eof => break,
                _ => continue,
            };
            if open.is_empty() && !tree.elements.is_empty() {
                return Err(XmlError { offset: start, message: "a second root element".into() });
            }
            let index = tree.push(text, &element, start)?;
            if let Some((parent, last)) = open.last_mut() {
                if *last == NONE {
                    tree.elements[*parent as usize].first_child = index;
                } else {
                    tree.elements[*last as usize].next_sibling = index;
                }
                *last = index;
            }
            if !empty {
                open.push((index, NONE));
            }
        }
        if let Some(&(index, _)) = open.last() {
            let e = &tree.elements[index as usize];
            let message = format!("<{}> is never closed", tree.names[index as usize]);
            return Err(XmlError { offset: e.start, message });
        }
        if tree.elements.is_empty() {
            return Err(XmlError { offset: 0, message: "no element".into() });
        }
        Ok(tree)
    }

    /// Adds the element `e` of `text`, which starts at byte `start`, and gives its index.
    fn push(&mut self, text: &'a str, e: &BytesStart<'_>, start: usize) -> Result<u32, XmlError> {
        let refuse = |message: String| XmlError { offset: start, message };
        let name =
            within(text, e.local_name().into_inner()).ok_or_else(|| refuse("a name that is not UTF-8".into()))?;
        let first = self.attributes.len();
        let raw = within(text, e.attributes_raw()).ok_or_else(|| refuse("attributes that are not UTF-8".into()))?;
        for attribute in Attributes(raw) {
            let (key, raw, entity) = attribute.map_err(refuse)?;
            if self.attributes[first..].iter().any(|(k, _)| same_name(k, key)) {
                return Err(refuse(format!("attribute {key} given twice")));
            }
            let value = if entity {
                quick_xml::escape::unescape(raw).map_err(|e| refuse(e.to_string()))?
            } else {
                Cow::Borrowed(raw)
            };
            self.attributes.push((key, value));
        }
        let count = u32::try_from(self.elements.len()).ok().filter(|&n| n != NONE);
        let index = count.ok_or_else(|| refuse("more elements than this reader takes".into()))?;
        self.names.push(name);
        self.elements.push(Element {
            attributes: (first as u32, self.attributes.len() as u32),
            first_child: NONE,
            next_sibling: NONE,
            text: NONE,
            start,
        });
        Ok(index)
    }

    /// Appends `text` to the text of element `parent`.
    fn add_text(&mut self, parent: u32, text: Cow<'a, str>) {
        let element = &mut self.elements[parent as usize];
        if element.text == NONE {
            element.text = self.texts.len() as u32;
            self.texts.push(text);
        } else {
            self.texts[element.text as usize].to_mut().push_str(&text);
        }
    }

    /// The root element.
    pub fn root(&self) -> Node<'_, 'a> {
        Node { tree: self, index: 0 }
    }
}

impl<'t, 'a> Node<'t, 'a> {
    fn element(&self) -> &'t Element {
        &self.tree.elements[self.index as usize]
    }

    /// Its name (without a namespace prefix).
    pub fn name(&self) -> &'t str {
        self.tree.names[self.index as usize]
    }

    /// Where it starts: the byte offset of its `<`.
    pub fn start(&self) -> usize {
        self.element().start
    }

    /// Its attributes: names and values.
    pub fn attributes(&self) -> impl Iterator<Item = (&'t str, &'t str)> + 't {
        let (first, end) = self.element().attributes;
        self.tree.attributes[first as usize..end as usize].iter().map(|(k, v)| (*k, v.as_ref()))
    }

    /// The value of its attribute `name`.
    pub fn attribute(&self, name: &str) -> Option<&'t str> {
        self.attributes().find(|(k, _)| same_name(k, name)).map(|(_, v)| v)
    }

    /// Its text (the text and CDATA directly inside it, joined).
    pub fn text(&self) -> Option<&'t str> {
        let text = self.element().text;
        (text != NONE).then(|| self.tree.texts[text as usize].as_ref())
    }

    /// Its child elements in order.
    pub fn children(&self) -> impl Iterator<Item = Node<'t, 'a>> + 't {
        let tree = self.tree;
        let mut next = self.element().first_child;
        std::iter::from_fn(move || {
            (next != NONE).then(|| {
                let node = Node { tree, index: next };
                next = tree.elements[next as usize].next_sibling;
                node
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elements_attributes_text_and_positions() {
        let text = "<?xml version=\"1.0\"?>\n<!DOCTYPE x>\n<a k=\"1 &amp; 2\">\n <b/><c x='y'>t&lt;<![CDATA[<u>]]>&#65;</c>\n</a>";
        let tree = Tree::parse(text).unwrap();
        let root = tree.root();
        assert_eq!((root.name(), root.attribute("k"), root.start()), ("a", Some("1 & 2"), 35));
        let kids: Vec<_> = root.children().collect();
        assert_eq!(kids.iter().map(|n| n.name()).collect::<Vec<_>>(), ["b", "c"]);
        assert_eq!((kids[1].attribute("x"), kids[1].text(), kids[0].text()), (Some("y"), Some("t<<u>A"), None));
        assert_eq!(&text[kids[1].start()..kids[1].start() + 2], "<c");
        assert_eq!(kids[1].attributes().count(), 1);
        let spaced = Tree::parse("<a\n\tx = \"1\"   y:z='\"2\"'\r\n/>").unwrap();
        let pairs: Vec<_> = spaced.root().attributes().collect();
        assert_eq!(pairs, [("x", "1"), ("y:z", "\"2\"")]);
    }

    #[test]
    fn what_is_not_a_tree_is_refused_with_its_place() {
        for (text, at) in [
            ("<a><b></a>", 6),
            ("<a>\n<b>", 4),
            ("<a/><a/>", 4),
            ("", 0),
            ("<a x='1' x='2'/>", 0),
            ("<a x=1/>", 0),
            ("<a x='&bogus;'/>", 0),
            ("<a x='&#xD800;'/>", 0),
            ("<a x='1'y='2'/>", 0),
            ("<a x='a<b'/>", 0),
            ("<a x/>", 0),
            ("<a ='1'/>", 0),
            ("<a x:'1'/>", 0),
            ("<a x=\"1'/>", 0),
        ] {
            let e = Tree::parse(text).err().unwrap_or_else(|| panic!("{text:?} accepted"));
            assert!(e.offset >= at && e.offset <= text.len(), "{text:?}: {e:?}");
        }
    }
}
