using System.Globalization;
using System.Text;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>'s chart: every configuration's error (the obstacle course's miss rate, from
/// <see cref="AccuracyReport.CourseMissRates"/>) against its cost per <c>Resolve</c> call, outdoors
/// and indoors, as an SVG with the Pareto front marked. The cost is a BenchmarkDotNet median ÷ the
/// median of the literal call in the same run, read from the CSV reports BenchmarkDotNet wrote
/// (<c>ResolveOutdoorBenchmarks</c> and <c>ResolveIndoorBenchmarks</c>, joined or not); where none
/// is found, from the ratios of the table committed in <c>docs/accuracy-vs-time.md</c>. Never timed here.
/// </summary>
internal static class AccuracyChart
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>The charted configurations: the course's name for it, the benchmark method measuring it, a short label.</summary>
    private static readonly (string Course, string Method, string Label)[] Configurations =
    [
        ("end-point (literal)", "Literal", "literal"),
        ("end-point (literal)", "NoEffects", "options, no effect"),
        ("step down 1.5 m", "StepDown", "step down 1.5 m*"),
        ("walkable slope", "WalkableSlope", "walkable slope"),
        ("swept 0.48 m", "Swept", "swept 0.48 m"),
        ("doors only", "DoorsOnly", "doors only"),
        ("body (the player's)", "BodyOnly", "body alone (player's)"),
        ("Player without body", "AllEffectsNoBody", "Player without body*"),
        ("Player (all effects, body)", "AllEffects", "Player (all effects, body)*"),
    ];

    /// <summary>
    /// The committed table's ratios (median ÷ the literal call's median, same run), used when no
    /// BenchmarkDotNet CSV is found: docs/accuracy-vs-time.md, "The table" (run 2 of 2026-11-27,
    /// outdoor 64 cells and 9 landblocks: literal 48.0 ns; indoor: literal 63.7 ns). Keep in step
    /// with that table when it is re-measured.
    /// </summary>
    private static readonly Dictionary<string, (double Outdoor, double Indoor)> CommittedRatios = new()
    {
        ["Literal"] = (1.00, 1.00),
        ["NoEffects"] = (0.98, 1.21),
        ["StepDown"] = (0.94, 1.23),
        ["WalkableSlope"] = (1.04, 1.24),
        ["Swept"] = (1.05, 1.25),
        ["DoorsOnly"] = (1.11, 1.21),
        ["BodyOnly"] = (2.20, 3.55),
        ["AllEffectsNoBody"] = (1.12, 1.20),
        ["AllEffects"] = (3.05, 3.78),
    };

    /// <summary>The row of <c>ResolveOutdoorBenchmarks</c> charted (its fullest world).</summary>
    private const string OutdoorCells = "64", OutdoorLandblocks = "9";

    private sealed record Point(int Number, string Label, double Error, double Ratio, double? Nanoseconds);

    private sealed record Panel(string Title, List<Point> Points, double LiteralNs);

    /// <summary>Writes the SVG to <paramref name="svgPath"/> and a Markdown section with its data to <paramref name="o"/>.</summary>
    public static void Write(TextWriter o, string svgPath, string resultsFolder)
    {
        IReadOnlyList<(string Name, double MissPercent)> misses = AccuracyReport.CourseMissRates;
        var error = misses.ToDictionary(m => m.Name, m => m.MissPercent);
        Dictionary<string, double>? outdoor = ReadMedians(resultsFolder, "ResolveOutdoorBenchmarks", out string? outdoorFile);
        Dictionary<string, double>? indoor = ReadMedians(resultsFolder, "ResolveIndoorBenchmarks", out string? indoorFile);
        bool measured = outdoor is not null && indoor is not null && Configurations.All(c => outdoor.ContainsKey(c.Method) && indoor.ContainsKey(c.Method));
        string source = measured
            ? $"BenchmarkDotNet CSV reports {Path.GetFileName(outdoorFile)} (outdoor, {OutdoorCells} cells × {OutdoorLandblocks} landblocks) and {Path.GetFileName(indoorFile)} (indoor), {File.GetLastWriteTimeUtc(indoorFile!).ToString("yyyy-MM-dd HH:mm", Inv)} UTC"
            : "the ratios of the table committed in docs/accuracy-vs-time.md (no complete BenchmarkDotNet CSV report of ResolveOutdoorBenchmarks and ResolveIndoorBenchmarks in " + resultsFolder + ")";

        Panel Build(string title, Dictionary<string, double>? medians, bool isOutdoor)
        {
            var points = new List<Point>();
            double literal = measured ? medians!["Literal"] : double.NaN;
            for (int i = 0; i < Configurations.Length; i++)
            {
                (string course, string method, string label) = Configurations[i];
                double ratio = measured ? medians![method] / literal : (isOutdoor ? CommittedRatios[method].Outdoor : CommittedRatios[method].Indoor);
                points.Add(new Point(i + 1, label, error[course], ratio, measured ? medians![method] : null));
            }

            return new Panel(title, points, literal);
        }

        Panel[] panels =
        [
            Build($"Outdoor: open ground ({OutdoorCells} buildings × {OutdoorLandblocks} landblocks, none near)", outdoor, isOutdoor: true),
            Build("Indoor: the 22 real Holtburg cells", indoor, isOutdoor: false),
        ];
        string caption = "Error: obstacle-course miss rate (seed 5, 1,600 courses × 5 speeds at 30 Hz): of the runs the truth (1 cm sub-steps, walkable slope) stops "
            + "before the obstacle, the share that ends more than 5 cm past it (* with step down: judged against the truth with step down 1.5 m and gravity). Cost: BenchmarkDotNet median per Resolve call (0.1–0.3 m moves) ÷ the literal call's median "
            + "in the same run and world, from " + source + ".";
        File.WriteAllText(svgPath, Svg(panels, caption));

        o.WriteLine("## Chart: error against cost");
        o.WriteLine();
        o.WriteLine($"Written to `{svgPath}`. {caption}");
        o.WriteLine();
        o.WriteLine("| # | configuration | course miss rate | outdoor × literal | indoor × literal | on the Pareto front (outdoor / indoor) |");
        o.WriteLine("| ---: | --- | ---: | ---: | ---: | --- |");
        bool[] frontOut = Front(panels[0].Points), frontIn = Front(panels[1].Points);
        for (int i = 0; i < Configurations.Length; i++)
        {
            Point a = panels[0].Points[i], b = panels[1].Points[i];
            o.WriteLine($"| {a.Number} | {a.Label} | {F(a.Error, "0.0")} % | {F(a.Ratio, "0.00")}{Ns(a)} | {F(b.Ratio, "0.00")}{Ns(b)} | {(frontOut[i] ? "yes" : "no")} / {(frontIn[i] ? "yes" : "no")} |");
        }

        o.WriteLine();

        static string Ns(Point p) => p.Nanoseconds is double ns ? $" ({F(ns, "0.0")} ns)" : string.Empty;
    }

    private static string F(double v, string format) => v.ToString(format, Inv);

    /// <summary>Which points no other point beats on both axes (cost and error, lower is better).</summary>
    private static bool[] Front(List<Point> points)
    {
        var front = new bool[points.Count];
        for (int i = 0; i < points.Count; i++)
        {
            Point p = points[i];
            front[i] = !points.Any(q => q != p && q.Ratio <= p.Ratio && q.Error <= p.Error && (q.Ratio < p.Ratio || q.Error < p.Error));
        }

        // Of identical points, the first stands for them.
        for (int i = 0; i < points.Count; i++)
        {
            for (int j = 0; j < i; j++)
            {
                if (front[i] && front[j] && points[i].Ratio == points[j].Ratio && points[i].Error == points[j].Error)
                {
                    front[i] = false;
                }
            }
        }

        return front;
    }

    // ------------------------------------------------------------------ CSV

    /// <summary>
    /// Median ns per method of <paramref name="type"/> from the newest CSV report in
    /// <paramref name="folder"/> that has its <c>Literal</c> row (a joined report has a <c>Type</c>
    /// column; a per-class report names the class in its file name). For the outdoor class, the row of
    /// <see cref="OutdoorCells"/> and <see cref="OutdoorLandblocks"/>. Null when none.
    /// </summary>
    private static Dictionary<string, double>? ReadMedians(string folder, string type, out string? file)
    {
        file = null;
        if (!Directory.Exists(folder))
        {
            return null;
        }

        foreach (string path in Directory.GetFiles(folder, "*-report.csv").OrderByDescending(File.GetLastWriteTimeUtc))
        {
            string[] lines = File.ReadAllLines(path);
            if (lines.Length < 2)
            {
                continue;
            }

            List<string> header = SplitCsv(lines[0]);
            int method = header.IndexOf("Method"), median = header.IndexOf("Median"), typeColumn = header.IndexOf("Type");
            int cells = header.IndexOf("Cells"), landblocks = header.IndexOf("Landblocks");
            if (method < 0 || median < 0 || (typeColumn < 0 && !Path.GetFileName(path).Contains("." + type + "-", StringComparison.Ordinal)))
            {
                continue;
            }

            var medians = new Dictionary<string, double>();
            foreach (string line in lines.Skip(1))
            {
                List<string> row = SplitCsv(line);
                if (row.Count != header.Count || (typeColumn >= 0 && row[typeColumn] != type)
                    || (type == "ResolveOutdoorBenchmarks" && (cells < 0 || landblocks < 0 || row[cells] != OutdoorCells || row[landblocks] != OutdoorLandblocks)))
                {
                    continue;
                }

                if (ParseNs(row[median]) is double ns)
                {
                    medians[row[method]] = ns;
                }
            }

            if (medians.ContainsKey("Literal"))
            {
                file = path;
                return medians;
            }
        }

        return null;
    }

    /// <summary>"1,234.5 ns", "1.2 μs", "1.2 us", "3 ms" → nanoseconds.</summary>
    private static double? ParseNs(string value)
    {
        string[] parts = value.Trim().Split(' ', StringSplitOptions.RemoveEmptyEntries);
        if (parts.Length != 2 || !double.TryParse(parts[0], NumberStyles.Float | NumberStyles.AllowThousands, Inv, out double v))
        {
            return null;
        }

        return parts[1] switch
        {
            "ns" => v,
            "us" or "μs" or "µs" => v * 1e3,
            "ms" => v * 1e6,
            "s" => v * 1e9,
            _ => null,
        };
    }

    private static List<string> SplitCsv(string line)
    {
        var fields = new List<string>();
        var field = new StringBuilder();
        bool quoted = false;
        foreach (char c in line)
        {
            if (c == '"')
            {
                quoted = !quoted;
            }
            else if (c == ',' && !quoted)
            {
                fields.Add(field.ToString());
                field.Clear();
            }
            else
            {
                field.Append(c);
            }
        }

        fields.Add(field.ToString());
        return fields;
    }

    // ------------------------------------------------------------------ SVG

    /// <summary>Run-to-run noise of a median on this project's 2-core VM (docs/accuracy-vs-time.md: ±10–20 %); drawn as a band.</summary>
    private const double Noise = 0.10;

    private const int Width = 1020, PanelWidth = 420, PlotHeight = 330, Top = 70, Left = 75, Gap = 85;

    private static string Svg(Panel[] panels, string caption)
    {
        double maxRatio = panels.SelectMany(p => p.Points).Max(p => p.Ratio);
        double maxError = panels.SelectMany(p => p.Points).Max(p => p.Error);
        double xMax = NiceCeiling(maxRatio * 1.08), yMax = NiceCeiling(Math.Max(maxError * 1.1, 1));
        const double xMin = 0.8;
        List<string> captionLines = Wrap(caption, 150);
        int legendTop = Top + PlotHeight + 60;
        int legendRows = (Configurations.Length + 2) / 3;
        int height = legendTop + (legendRows * 18) + 66 + (captionLines.Count * 15) + 10;

        var s = new StringBuilder();
        s.AppendLine(CultureInfo.InvariantCulture, $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{height}\" viewBox=\"0 0 {Width} {height}\" font-family=\"sans-serif\" font-size=\"12\">");
        s.AppendLine("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
        s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{Width / 2}\" y=\"24\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">What accuracy costs: each configuration's error against its cost per Resolve call</text>");
        for (int k = 0; k < panels.Length; k++)
        {
            int x0 = Left + (k * (PanelWidth + Gap));
            DrawPanel(s, panels[k], x0, xMin, xMax, yMax);
        }

        // Legend: numbers, and the marks.
        for (int i = 0; i < Configurations.Length; i++)
        {
            int col = i % 3, row = i / 3;
            double x = Left + (col * 300), y = legendTop + (row * 18);
            s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{x}\" y=\"{y}\"><tspan font-weight=\"bold\">{i + 1}</tspan>  {Escape(panels[0].Points[i].Label)}</text>");
        }

        double ly = legendTop + (legendRows * 18) + 4;
        s.AppendLine(CultureInfo.InvariantCulture, $"<circle cx=\"{Left + 6}\" cy=\"{ly - 4}\" r=\"5\" fill=\"#d62728\" stroke=\"#7f1010\"/>");
        s.AppendLine(CultureInfo.InvariantCulture, $"<line x1=\"{Left + 16}\" y1=\"{ly - 4}\" x2=\"{Left + 40}\" y2=\"{ly - 4}\" stroke=\"#d62728\" stroke-width=\"2.5\"/>");
        s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{Left + 48}\" y=\"{ly}\">Pareto front (joined): no other configuration is both cheaper and more accurate; lower left is better</text>");
        ly += 18;
        s.AppendLine(CultureInfo.InvariantCulture, $"<circle cx=\"{Left + 6}\" cy=\"{ly - 4}\" r=\"5\" fill=\"white\" stroke=\"#777\" stroke-width=\"1.5\"/>");
        s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{Left + 48}\" y=\"{ly}\">dominated: another configuration is at least as cheap and as accurate, and better in one</text>");
        ly += 18;
        s.AppendLine(CultureInfo.InvariantCulture, $"<rect x=\"{Left}\" y=\"{ly - 10}\" width=\"40\" height=\"10\" fill=\"#9ecae1\" fill-opacity=\"0.35\"/>");
        s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{Left + 48}\" y=\"{ly}\">within ±{Noise * 100:0} % of the literal call: differences this small move from run to run on this machine (read them as equal)</text>");

        double cy = ly + 22;
        foreach (string line in captionLines)
        {
            s.AppendLine(CultureInfo.InvariantCulture, $"<text x=\"{Left - 50}\" y=\"{cy}\" font-size=\"11\" fill=\"#333\">{Escape(line)}</text>");
            cy += 15;
        }

        s.AppendLine("</svg>");
        return s.ToString();
    }

    private static void DrawPanel(StringBuilder s, Panel panel, int x0, double xMin, double xMax, double yMax)
    {
        double X(double ratio) => x0 + ((ratio - xMin) / (xMax - xMin) * PanelWidth);
        double Y(double error) => Top + PlotHeight - (error / yMax * PlotHeight);
        var inv = CultureInfo.InvariantCulture;

        s.AppendLine(inv, $"<text x=\"{x0 + (PanelWidth / 2)}\" y=\"{Top - 12}\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">{Escape(panel.Title)}</text>");
        s.AppendLine(inv, $"<rect x=\"{x0}\" y=\"{Top}\" width=\"{PanelWidth}\" height=\"{PlotHeight}\" fill=\"none\" stroke=\"#444\"/>");

        // The noise band around the literal call, then the grid and ticks.
        s.AppendLine(inv, $"<rect x=\"{X(1 - Noise):0.#}\" y=\"{Top}\" width=\"{X(1 + Noise) - X(1 - Noise):0.#}\" height=\"{PlotHeight}\" fill=\"#9ecae1\" fill-opacity=\"0.35\"/>");
        double xStep = TickStep(xMax - xMin), yStep = TickStep(yMax);
        for (double t = Math.Ceiling(xMin / xStep) * xStep; t <= xMax + 1e-9; t += xStep)
        {
            double x = X(t);
            s.AppendLine(inv, $"<line x1=\"{x:0.#}\" y1=\"{Top}\" x2=\"{x:0.#}\" y2=\"{Top + PlotHeight}\" stroke=\"#e4e4e4\"/>");
            s.AppendLine(inv, $"<text x=\"{x:0.#}\" y=\"{Top + PlotHeight + 16}\" text-anchor=\"middle\">{t.ToString("0.##", inv)}×</text>");
        }

        for (double t = 0; t <= yMax + 1e-9; t += yStep)
        {
            double y = Y(t);
            s.AppendLine(inv, $"<line x1=\"{x0}\" y1=\"{y:0.#}\" x2=\"{x0 + PanelWidth}\" y2=\"{y:0.#}\" stroke=\"#e4e4e4\"/>");
            s.AppendLine(inv, $"<text x=\"{x0 - 6}\" y=\"{y + 4:0.#}\" text-anchor=\"end\">{t.ToString("0.##", inv)} %</text>");
        }

        string literal = double.IsNaN(panel.LiteralNs) ? "the literal call" : $"the literal call ({panel.LiteralNs.ToString("0.0", inv)} ns)";
        s.AppendLine(inv, $"<text x=\"{x0 + (PanelWidth / 2)}\" y=\"{Top + PlotHeight + 36}\" text-anchor=\"middle\">cost per call, × {Escape(literal)}, median</text>");
        s.AppendLine(inv, $"<text transform=\"translate({x0 - 48},{Top + (PlotHeight / 2)}) rotate(-90)\" text-anchor=\"middle\">obstacle-course miss rate (% of runs that should stop)</text>");

        // The front: joined in order of cost.
        bool[] front = Front(panel.Points);
        List<Point> onFront = panel.Points.Where((p, i) => front[i]).OrderBy(p => p.Ratio).ToList();
        if (onFront.Count > 1)
        {
            string path = string.Join(" ", onFront.Select((p, i) => $"{(i == 0 ? "M" : "L")}{X(p.Ratio).ToString("0.#", inv)},{Y(p.Error).ToString("0.#", inv)}"));
            s.AppendLine(inv, $"<path d=\"{path}\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\" stroke-opacity=\"0.8\"/>");
        }

        // Points (dominated first, so the front's marks are on top), then numbered labels placed clear of each other.
        var labels = new List<(double X, double Y, double W)>();
        foreach (int i in Enumerable.Range(0, panel.Points.Count).OrderBy(i => front[i]))
        {
            Point p = panel.Points[i];
            string title = Escape($"{p.Number} {p.Label}: miss rate {p.Error.ToString("0.0", inv)} %, {p.Ratio.ToString("0.00", inv)}× literal{(p.Nanoseconds is double ns ? $" ({ns.ToString("0.0", inv)} ns)" : string.Empty)}");
            string mark = front[i]
                ? "r=\"5.5\" fill=\"#d62728\" stroke=\"#7f1010\""
                : "r=\"5\" fill=\"white\" stroke=\"#777\" stroke-width=\"1.5\"";
            s.AppendLine(inv, $"<circle cx=\"{X(p.Ratio):0.#}\" cy=\"{Y(p.Error):0.#}\" {mark}><title>{title}</title></circle>");
        }

        foreach (Point p in panel.Points.OrderBy(p => p.Ratio))
        {
            double px = X(p.Ratio), py = Y(p.Error), w = 8 * p.Number.ToString(inv).Length;
            (double dx, double dy)[] tries = [(7, -7), (7, 13), (-7 - w, -7), (-7 - w, 13), (7, -20), (7, 26), (-7 - w, -20), (-7 - w, 26), (20, -7), (20, 13), (-20 - w, -7), (-20 - w, 13), (7, -33), (7, 39)];
            (double lx, double ly) = (px + tries[0].dx, py + tries[0].dy);
            foreach ((double dx, double dy) in tries)
            {
                (double cx, double cy) = (px + dx, py + dy);
                if (!labels.Any(l => cx < l.X + l.W + 2 && l.X < cx + w + 2 && Math.Abs(cy - l.Y) < 13))
                {
                    (lx, ly) = (cx, cy);
                    break;
                }
            }

            labels.Add((lx, ly, w));
            s.AppendLine(inv, $"<text x=\"{lx:0.#}\" y=\"{ly:0.#}\" font-weight=\"bold\">{p.Number}</text>");
        }
    }

    private static double NiceCeiling(double v)
    {
        double step = TickStep(v);
        return Math.Ceiling(v / step) * step;
    }

    /// <summary>A round tick spacing giving about 5–10 ticks over <paramref name="range"/>.</summary>
    private static double TickStep(double range)
    {
        double raw = range / 6, magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        double n = raw / magnitude;
        return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * magnitude;
    }

    private static List<string> Wrap(string text, int width)
    {
        var lines = new List<string>();
        var line = new StringBuilder();
        foreach (string word in text.Split(' '))
        {
            if (line.Length > 0 && line.Length + 1 + word.Length > width)
            {
                lines.Add(line.ToString());
                line.Clear();
            }

            line.Append(line.Length > 0 ? " " : string.Empty).Append(word);
        }

        lines.Add(line.ToString());
        return lines;
    }

    private static string Escape(string text) => text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal).Replace(">", "&gt;", StringComparison.Ordinal).Replace("\"", "&quot;", StringComparison.Ordinal);
}
