using System.Numerics;
using System.Text;
using System.Xml.Linq;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

// The route: the body's clearance at walls, the eye's path, and the feet's path coloured by cell.
internal static partial class WalkSvg
{
    /// <summary>
    /// The body's clearance where it touched a wall: a circle of the body's radius (<paramref name="radius"/>,
    /// in pixels) around the feet at each frame the engine answered <see cref="ResolveOutcome.Slid"/>
    /// along a wall (a horizontal normal; a slide along a slope's contour touched no wall) or refused as
    /// <see cref="ResolveOutcome.Wall"/>. A frame whose circle would lie within a quarter of the radius of
    /// the last one drawn is left out, so a long slide is a row of circles, not a solid band.
    /// </summary>
    private static XElement Clearance(IReadOnlyList<FrameSample> samples, float radius, Func<FrameSample, Vector2> place)
    {
        var group = new XElement(Svg + "g", new XAttribute("id", "body-clearance"), new XAttribute("fill", "none"), new XAttribute("stroke", ClearanceColour), Attr("stroke-width", 0.6f));
        Vector2? last = null;
        foreach (FrameSample sample in samples)
        {
            bool touched = sample.Slide is Vector3 normal ? normal.Z == 0f : sample.Refusal == ResolveOutcome.Wall;
            Vector2 p = place(sample);
            if (touched && (last is not Vector2 previous || Vector2.Distance(p, previous) >= radius / 4f))
            {
                group.Add(new XElement(Svg + "circle", Attr("cx", p.X), Attr("cy", p.Y), Attr("r", radius), new XElement(Svg + "title", Invariant($"frame {sample.Frame}: ({sample.Position.X:F3}, {sample.Position.Y:F3})"))));
                last = p;
            }
        }

        return group;
    }

    /// <summary>
    /// The chase camera's eye (<see cref="FrameSample.Camera"/>) in <see cref="EyeColour"/>: one line through the frames'
    /// eyes, titled with the frames pulled in: on the map through those at least <see cref="EyePathSpacing"/> apart
    /// (<paramref name="ground"/>: where each is, metres) and the last; with no <paramref name="ground"/>, through every frame's.
    /// </summary>
    private static XElement EyePath(IReadOnlyList<FrameSample> samples, Func<FrameSample, Vector2> place, Func<FrameSample, Vector2>? ground)
    {
        var points = new StringBuilder();
        Vector2? last = null;
        for (int i = 0; i < samples.Count; i++)
        {
            Vector2 at = ground?.Invoke(samples[i]) ?? default;
            if (ground is null || last is not Vector2 previous || Vector2.Distance(at, previous) >= EyePathSpacing || i == samples.Count - 1)
            {
                Vector2 p = place(samples[i]);
                points.Append(Invariant($"{p.X:0.##},{p.Y:0.##} "));
                last = at;
            }
        }

        int pulled = samples.Count(s => s.Camera.PulledIn);
        return new XElement(Svg + "polyline", new XAttribute("class", "camera-eye"), new XAttribute("points", points.ToString().TrimEnd()),
            new XAttribute("fill", "none"), new XAttribute("stroke", EyeColour), Attr("stroke-width", 1f), Attr("stroke-opacity", 0.8f),
            new XElement(Svg + "title", Invariant($"the chase camera's eye: {samples.Count} frames, pulled in at {pulled}")));
    }

    /// <summary>Indoor cells get distinct hues in order of first visit; outdoor cells alternate two greys.</summary>
    private static Dictionary<uint, string> Colours(WalkRecord record)
    {
        var colours = new Dictionary<uint, string>();
        int indoor = 0, outdoor = 0;
        foreach ((int _, uint cell) in record.CellVisits())
        {
            if (colours.ContainsKey(cell))
            {
                continue;
            }

            colours[cell] = CellIds.IsIndoor(cell)
                ? Invariant($"hsl({(indoor++ * 137.508) % 360:0},75%,42%)")
                : (outdoor++ % 2 == 0 ? "#333333" : "#888888");
        }

        return colours;
    }

    private static void AddRoute(XElement parent, IReadOnlyList<FrameSample> samples, Dictionary<uint, string> colours, Func<FrameSample, Vector2> place)
    {
        int i = 0;
        while (i < samples.Count)
        {
            int j = i;
            while (j + 1 < samples.Count && samples[j + 1].CellId == samples[i].CellId)
            {
                j++;
            }

            // Each run starts at the previous run's last point, so the line has no gaps.
            var points = new StringBuilder();
            for (int k = Math.Max(0, i - 1); k <= j; k++)
            {
                Vector2 p = place(samples[k]);
                points.Append(Invariant($"{p.X:0.##},{p.Y:0.##} "));
            }

            parent.Add(new XElement(Svg + "polyline",
                new XAttribute("points", points.ToString().TrimEnd()),
                new XAttribute("fill", "none"),
                new XAttribute("stroke", colours[samples[i].CellId]),
                Attr("stroke-width", 2.5f),
                new XElement(Svg + "title", $"0x{samples[i].CellId:X8} {HoltburgWorld.CellName(samples[i].CellId)}".TrimEnd())));
            i = j + 1;
        }
    }
}
