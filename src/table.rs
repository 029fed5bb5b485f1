//! Tables of text: the tools collect rows of cells and render them once, as Markdown (the
//! benchmark's summary.md) or as aligned columns (a terminal).

#![warn(missing_docs)]

/// Where a column's cells sit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Align {
    /// Flush left: names and words.
    #[default]
    Left,
    /// Flush right: numbers.
    Right,
}

/// A table: a heading and an alignment per column, and rows of cells.
///
/// The table has as many columns as its widest row or its headings; a missing heading, cell
/// or alignment is empty or [`Align::Left`].
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Table {
    /// The heading of each column.
    pub headers: Vec<String>,
    /// The alignment of each column.
    pub align: Vec<Align>,
    /// The cells, row by row.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with these columns (heading and alignment) and no rows.
    pub fn new<S: Into<String>>(columns: impl IntoIterator<Item = (S, Align)>) -> Table {
        let mut table = Table::default();
        for (header, align) in columns {
            table.column(header, align);
        }
        table
    }

    /// Adds a column on the right.
    pub fn column(&mut self, header: impl Into<String>, align: Align) {
        self.headers.push(header.into());
        self.align.push(align);
    }

    /// Adds a row at the bottom.
    pub fn row<S: Into<String>>(&mut self, cells: impl IntoIterator<Item = S>) {
        self.rows.push(cells.into_iter().map(Into::into).collect());
    }

    fn columns(&self) -> usize {
        self.rows
            .iter()
            .map(Vec::len)
            .chain([self.headers.len(), self.align.len()])
            .max()
            .unwrap_or(0)
    }

    fn align(&self, column: usize) -> Align {
        self.align.get(column).copied().unwrap_or_default()
    }

    /// The headings, then each row, with every column: missing cells are empty.
    fn lines(&self) -> impl Iterator<Item = Vec<&str>> {
        let columns = self.columns();
        std::iter::once(&self.headers)
            .chain(&self.rows)
            .map(move |cells| {
                (0..columns)
                    .map(|i| cells.get(i).map_or("", String::as_str))
                    .collect()
            })
    }

    /// GitHub-flavoured Markdown: `| a | b |` lines, the rule under the headings marks right
    /// alignment (`---:`). A `|` in a cell is escaped and a line break becomes a space. A
    /// table without columns is empty.
    pub fn markdown(&self) -> String {
        let mut out = String::new();
        if self.columns() == 0 {
            return out;
        }
        for (i, cells) in self.lines().enumerate() {
            out.push('|');
            for cell in cells {
                if !cell.is_empty() {
                    out.push(' ');
                    out.push_str(&cell.replace('|', "\\|").replace(['\r', '\n'], " "));
                }
                out.push_str(" |");
            }
            out.push('\n');
            if i == 0 {
                out.push('|');
                for column in 0..self.columns() {
                    out.push_str(match self.align(column) {
                        Align::Left => " --- |",
                        Align::Right => " ---: |",
                    });
                }
                out.push('\n');
            }
        }
        out
    }

    /// Plain text for a terminal: every column as wide as its widest cell (in characters),
    /// two spaces between columns, no spaces at the ends of lines. A table without columns is
    /// empty.
    pub fn text(&self) -> String {
        if self.columns() == 0 {
            return String::new();
        }
        let mut widths = vec![0; self.columns()];
        for cells in self.lines() {
            for (width, cell) in widths.iter_mut().zip(cells) {
                *width = (*width).max(cell.chars().count());
            }
        }
        let mut out = String::new();
        for cells in self.lines() {
            let mut line = String::new();
            for (column, (cell, &width)) in cells.iter().zip(&widths).enumerate() {
                if column > 0 {
                    line.push_str("  ");
                }
                let pad = " ".repeat(width - cell.chars().count());
                match self.align(column) {
                    Align::Left => {
                        line.push_str(cell);
                        line.push_str(&pad);
                    }
                    Align::Right => {
                        line.push_str(&pad);
                        line.push_str(cell);
                    }
                }
            }
            out.push_str(line.trim_end());
            out.push('\n');
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Table {
        let mut t = Table::new([("mode", Align::Left), ("time (ms)", Align::Right)]);
        t.row(["vertex", "1.25"]);
        t.row(["fragment²", "12.5"]);
        t
    }

    #[test]
    fn markdown_marks_right_alignment_in_the_rule() {
        assert_eq!(
            sample().markdown(),
            "| mode | time (ms) |\n| --- | ---: |\n| vertex | 1.25 |\n| fragment² | 12.5 |\n"
        );
    }

    #[test]
    fn markdown_leaves_empty_cells_empty_and_escapes_pipes() {
        let mut t = Table::new([("", Align::Left), ("", Align::Left)]);
        t.row(["note", "a | b\nc"]);
        t.row(["", "x"]);
        assert_eq!(
            t.markdown(),
            "| | |\n| --- | --- |\n| note | a \\| b c |\n| | x |\n"
        );
    }

    #[test]
    fn text_pads_columns_to_their_widest_cell_in_characters() {
        assert_eq!(
            sample().text(),
            "mode       time (ms)\nvertex          1.25\nfragment²       12.5\n"
        );
    }

    #[test]
    fn short_rows_and_missing_alignments_fill_in() {
        let mut t = Table::new([("a", Align::Right)]);
        t.row(["1", "extra"]);
        t.row(["22"]);
        assert_eq!(t.text(), " a\n 1  extra\n22\n");
        assert_eq!(t.markdown(), "| a | |\n| ---: | --- |\n| 1 | extra |\n| 22 | |\n");
    }

    #[test]
    fn an_empty_table_is_empty() {
        assert_eq!(Table::default().text(), "");
        assert_eq!(Table::default().markdown(), "");
    }
}
