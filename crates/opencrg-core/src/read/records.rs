//! Decoding of the data section: one record (all channels of one cross section) at a time.
//!
//! Text formats (LRFI, LDFI) use fixed-width fields; a record starts on a new line
//! and spans as many 80-character lines as its channels need. A field that is not a
//! number is NaN (the `**unused**` placeholder reads as 0, as in the reference).
//! Binary formats (KRBI, KDBI) are big-endian IEEE numbers, records packed one
//! after another.

use crate::model::header::DataFormat;
use crate::read::syntax::parse_f64_prefix;
use byteorder::{BigEndian, ByteOrder};

/// Why decoding stopped early.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Truncated {
    /// 1-based number of the incomplete record.
    pub record: usize,
    /// How many of its channels were complete.
    pub channels_read: usize,
}

/// Calls `sink` with every complete record and the offset just past it, and returns
/// how many records there were.
///
/// Binary data stops after `max_records` (the count the header declares); text data
/// runs to the end of the buffer. An incomplete record that is not just trailing
/// blank space is reported as [`Truncated`].
pub(crate) fn decode<E>(
    format: DataFormat,
    channels: usize,
    data: &[u8],
    max_records: usize,
    mut sink: impl FnMut(usize, &[f64], usize) -> Result<(), E>,
) -> Result<Result<usize, Truncated>, E> {
    let mut record = vec![0.0f64; channels];
    if channels == 0 {
        return Ok(Ok(0));
    }
    if format.is_text() {
        return decode_text(format, data, &mut record, &mut sink);
    }
    let width = format.field_width();
    let size = width * channels;
    let mut count = 0;
    for chunk in data.chunks(size).take(max_records) {
        if chunk.len() < size {
            return Ok(Err(Truncated { record: count + 1, channels_read: chunk.len() / width }));
        }
        for (value, bytes) in record.iter_mut().zip(chunk.chunks_exact(width)) {
            *value = if width == 4 { f64::from(BigEndian::read_f32(bytes)) } else { BigEndian::read_f64(bytes) };
        }
        count += 1;
        sink(count - 1, &record, count * size)?;
    }
    Ok(Ok(count))
}

fn is_newline(b: u8) -> bool {
    b == b'\n' || b == b'\r'
}

fn decode_text<E>(
    format: DataFormat,
    data: &[u8],
    record: &mut [f64],
    sink: &mut impl FnMut(usize, &[f64], usize) -> Result<(), E>,
) -> Result<Result<usize, Truncated>, E> {
    let width = format.field_width();
    let bytes_per_record = width * record.len();
    let lines_per_record = bytes_per_record.div_ceil(80);
    let mut pos = 0;
    let mut count = 0;
    loop {
        while pos < data.len() && is_newline(data[pos]) {
            pos += 1;
        }
        if pos >= data.len() {
            return Ok(Ok(count));
        }
        let start = pos;
        for _ in 0..lines_per_record {
            match data[pos..].iter().position(|&b| is_newline(b)) {
                Some(n) => {
                    pos += n;
                    pos += if data[pos] == b'\r' && data.get(pos + 1) == Some(&b'\n') { 2 } else { 1 };
                }
                None => {
                    pos = data.len();
                    break;
                }
            }
        }
        let body = &data[start..pos];
        let mut at = 0;
        for (i, value) in record.iter_mut().enumerate() {
            while at < body.len() && is_newline(body[at]) {
                at += 1;
            }
            if body.len() - at < width {
                let trailing_blank = body.iter().all(|b| b.is_ascii_whitespace());
                return Ok(if trailing_blank && i == 0 {
                    Ok(count)
                } else {
                    Err(Truncated { record: count + 1, channels_read: i })
                });
            }
            *value = text_field(&body[at..at + width]);
            at += width;
        }
        sink(count, record, pos)?;
        count += 1;
    }
}

/// Reads one fixed-width text field the way the reference does.
#[inline]
pub(crate) fn text_field(field: &[u8]) -> f64 {
    if let Some(v) = plain_decimal(field) {
        return v;
    }
    const NUMERIC: &[u8] = b"0123456789+-.eEdD ";
    if field.iter().all(|b| NUMERIC.contains(b)) {
        // Only ASCII here, so the bytes are valid UTF-8.
        let text = std::str::from_utf8(field).unwrap_or("");
        parse_f64_prefix(text).unwrap_or(0.0)
    } else if field == b"**unused**" {
        0.0
    } else {
        f64::NAN
    }
}

/// Powers of ten that f64 holds exactly.
const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
    1e21, 1e22,
];

/// The common field, quickly: blanks, an optional sign, digits with at most one
/// point, an optional exponent (`e`/`E`, optional sign, digits), and nothing after.
/// Answers only where one rounding gives the exact result (at most 2^53 as the
/// digits' integer, a power of ten up to 22: both exact in f64, so one
/// multiplication or division rounds the true value correctly, as a full parser
/// does); `None` for everything else, which the general parser reads.
#[inline]
fn plain_decimal(field: &[u8]) -> Option<f64> {
    let mut i = field.iter().position(|&b| b != b' ')?;
    let negative = field[i] == b'-';
    if matches!(field[i], b'-' | b'+') {
        i += 1;
    }
    let (mut mantissa, mut digits, mut scale) = (0u64, 0u32, 0i32);
    let mut point = false;
    while let Some(&b) = field.get(i) {
        match b {
            b'0'..=b'9' => {
                mantissa = mantissa * 10 + u64::from(b - b'0');
                digits += 1;
                scale -= i32::from(point);
                if digits > 18 {
                    return None;
                }
            }
            b'.' if !point => point = true,
            _ => break,
        }
        i += 1;
    }
    if digits == 0 {
        return None;
    }
    if let Some(b'e' | b'E') = field.get(i) {
        i += 1;
        let exp_negative = field.get(i) == Some(&b'-');
        if matches!(field.get(i), Some(b'-' | b'+')) {
            i += 1;
        }
        let (mut exp, mut exp_digits) = (0i32, 0);
        while let Some(&b @ b'0'..=b'9') = field.get(i) {
            exp = exp * 10 + i32::from(b - b'0');
            exp_digits += 1;
            if exp_digits > 4 {
                return None;
            }
            i += 1;
        }
        if exp_digits == 0 {
            return None;
        }
        scale += if exp_negative { -exp } else { exp };
    }
    if i != field.len() || mantissa > 1 << 53 {
        return None;
    }
    let m = mantissa as f64;
    let power = *EXACT_POWERS_OF_TEN.get(scale.unsigned_abs() as usize)?;
    let v = if scale < 0 { m / power } else { m * power };
    Some(if negative { -v } else { v })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The general reading of a field (what `text_field` does without the quick path).
    fn general(field: &[u8]) -> f64 {
        parse_f64_prefix(std::str::from_utf8(field).unwrap()).unwrap_or(0.0)
    }

    #[test]
    fn quick_decimals_equal_the_general_parser() {
        // Formatted numbers of every magnitude, and random strings of number characters.
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut quick = 0;
        for k in 0..200_000 {
            let text = if k % 2 == 0 {
                let x = f64::from_bits(next() >> 2) * if next() % 2 == 0 { 1.0 } else { -1.0 };
                let x = x.clamp(-1e30, 1e30) * 10f64.powi((next() % 40) as i32 - 30);
                match k % 6 {
                    0 => format!("{x:10.5}"),
                    2 => format!("{x:10.3e}"),
                    _ => format!("{x:10}"),
                }
            } else {
                const CHARS: &[u8] = b"0123456789+-.eE ";
                (0..10).map(|_| CHARS[(next() % CHARS.len() as u64) as usize] as char).collect()
            };
            let field = &text.as_bytes()[..10.min(text.len())];
            if let Some(v) = plain_decimal(field) {
                quick += 1;
                assert_eq!(v.to_bits(), general(field).to_bits(), "field {:?}", text);
            }
        }
        assert!(quick > 50_000, "{quick} fields read the quick way");
        for (field, value) in [(&b"0.00084539"[..], 0.00084539f64), (b"3.46225e-4", 3.46225e-4), (b"  -0.00000", -0.0)]
        {
            assert_eq!(plain_decimal(field).map(f64::to_bits), Some(value.to_bits()));
        }
        for field in [&b"1.5e      "[..], b"1d5       ", b"          ", b"1.2.3     ", b"1e400     "] {
            assert_eq!(plain_decimal(field), None, "{:?}", std::str::from_utf8(field));
        }
    }

    fn collect(format: DataFormat, n: usize, data: &[u8], max: usize) -> (Vec<Vec<f64>>, Result<usize, Truncated>) {
        let mut rows = Vec::new();
        let r = decode::<()>(format, n, data, max, |_, r, _| {
            rows.push(r.to_vec());
            Ok(())
        })
        .unwrap();
        (rows, r)
    }

    #[test]
    fn text_records_wrap_and_touch() {
        let row2: String = [
            "**********",
            "       0.5",
            "       1.0",
            "       2.0",
            "       3.0",
            "       4.0",
            "       5.0",
            "       6.0",
        ]
        .concat();
        let text = format!(
            " 1.0000000-2.0000000 3.0000000 4.0000000 5.0000000 6.0000000 7.0000000 8.0000000\n 9.0000000\n{row2}\n       1.5\n"
        );
        let data = text.as_bytes();
        let (rows, r) = collect(DataFormat::Lrfi, 9, data, usize::MAX);
        assert_eq!(r, Ok(2));
        assert_eq!(rows[0], vec![1.0, -2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        assert!(rows[1][0].is_nan());
        assert_eq!(rows[1][8], 1.5);
    }

    #[test]
    fn truncated_text_is_reported() {
        let (_, r) = collect(DataFormat::Lrfi, 3, b" 1.0000000 2.0000000 3.0000000\n 1.0000000\n", usize::MAX);
        assert_eq!(r, Err(Truncated { record: 2, channels_read: 1 }));
    }

    #[test]
    fn binary_records() {
        let mut data = Vec::new();
        for v in [1.0f32, 2.0, 3.0, 4.0, f32::NAN] {
            data.extend_from_slice(&v.to_be_bytes());
        }
        let (rows, r) = collect(DataFormat::Krbi, 2, &data, 2);
        assert_eq!(r, Ok(2));
        assert_eq!(rows, vec![vec![1.0, 2.0], vec![3.0, 4.0]]);
        let (_, r) = collect(DataFormat::Krbi, 2, &data[..12], 2);
        assert_eq!(r, Err(Truncated { record: 2, channels_read: 1 }));
    }

    #[test]
    fn unused_placeholder() {
        assert_eq!(text_field(b"**unused**"), 0.0);
        assert!(text_field(b"*****nan**").is_nan());
        assert_eq!(text_field(b"          "), 0.0);
    }
}
