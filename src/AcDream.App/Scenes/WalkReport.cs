using System.Globalization;
using System.Numerics;
using System.Text;
using AcDream.Core.Physics;
using AcDream.App.Movement;
using AcDream.App.World;

namespace AcDream.App.Scenes;

/// <summary>The summary a person reads after a run: cells, refusals, airborne frames, streaming, the end.</summary>
internal static partial class WalkReport
{
    /// <summary>Formats <paramref name="record"/>; <paramref name="svgPath"/> is printed last.</summary>
    public static string Format(WalkRecord record, string svgPath)
    {
        var text = new StringBuilder();
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));

        int frames = record.Final.Frame;
        Line($"Scene \"{record.Scene.Name}\" ({record.Scene.Source}): {frames} frames at {SceneRunner.FramesPerSecond} Hz, {frames / (float)SceneRunner.FramesPerSecond:F1} s simulated{(record.Truncated ? ", stopped early by --frames" : "")}.");
        Line($"Effects: {DescribeEffects(record.Scene.Effects)}.");
        text.AppendLine();

        Line($"Cells visited (frame entered):");
        IReadOnlyList<(int Frame, uint CellId)> visits = record.CellVisits();
        for (int i = 0; i < visits.Count; i++)
        {
            (int frame, uint cell) = visits[i];
            if (!CellIds.IsIndoor(cell))
            {
                // A run of outdoor cells is one line.
                int j = i;
                while (j + 1 < visits.Count && !CellIds.IsIndoor(visits[j + 1].CellId))
                {
                    j++;
                }

                string seams = string.Join(", ", Seams(visits, i, j));
                Line($"  {frame,5}  outdoors, {j - i + 1} cell{(j > i ? "s" : "")} 0x{cell:X8}{(j > i ? $" .. 0x{visits[j].CellId:X8}" : "")}{(seams.Length > 0 ? $"; seam {seams}" : "")}");
                i = j;
            }
            else
            {
                Line($"  {frame,5}  0x{cell:X8}  {HoltburgWorld.CellName(cell) ?? "indoors"}");
            }
        }

        text.AppendLine();
        Line($"Legs:");
        int number = 1;
        foreach (LegResult leg in record.Legs)
        {
            string outcome = leg.Leg.To is null ? (leg.Reached ? "done" : "cut short") : (leg.Reached ? "reached" : "NOT reached");
            string refused = leg.Refusals.Count == 0 ? "" : "; refused " + string.Join(", ", leg.Refusals.OrderBy(r => r.Key).Select(r => $"{r.Value} × {Describe(r.Key)}"));
            string slid = leg.Slides.Count == 0 ? "" : "; slid " + DescribeSlides(leg.Slides);
            Line($"  {number++,2}. {leg.Leg.Name}: {outcome}, frames {leg.FirstFrame}-{leg.LastFrame}{slid}{refused}{DescribeAir(leg.Air)}{DescribeLegMovers(record, leg)}");
        }

        text.AppendLine();
        AddCamera(text, record);
        AddPointers(text, record);
        Line($"Refused moves: {string.Join(", ", Refusals.Select(o => $"{record.RefusalCount(o)} {Describe(o)}"))}.");
        int wallSlides = record.Samples.Count(s => s.Slide is Vector3 n && IsWall(n));
        Line($"Slid moves: {wallSlides} along walls, {record.SlideCount - wallSlides} along slopes' contours.");
        AddObjects(text, record);
        AddMovers(text, record);
        (int jumps, int headHits, int landings, int edgeSlides) = record.Air;
        Line($"Jumps: {jumps}; head hits: {headHits}; landings: {landings}; edge slides (held at a floor's edge): {edgeSlides}.");
        Line($"Airborne: {record.AirborneFrames} frames.");
        foreach (Fall fall in record.Falls())
        {
            if (fall.LandingFrame < 0)
            {
                Line($"Fall from frame {fall.TakeOffFrame} at {fall.FromZ:F2} m: still airborne at the end ({fall.LandingZ:F2} m).");
                continue;
            }

            Line($"Fall from frame {fall.TakeOffFrame} at {fall.FromZ:F2} m: {fall.AirborneFrames} frames airborne under gravity, landed at frame {fall.LandingFrame} on {fall.LandingZ:F3} m in 0x{fall.LandingCellId:X8}.");
        }

        foreach (Drop drop in record.Drops)
        {
            Line($"Drop at frame {drop.Frame}: {drop.FromZ:F2} m (0x{drop.FromCellId:X8}) to {drop.ToZ:F2} m (0x{drop.ToCellId:X8}) in one frame: without the step-down effect the engine puts the mover on the floor below at once (set \"effects\" in the scene for a fall).");
        }

        int loaded = record.Streaming.Count(e => e.Loaded), unloaded = record.Streaming.Count(e => !e.Loaded);
        Line($"Landblocks: {loaded} loaded, {unloaded} unloaded (window {2 * GameWindow.StreamingRadius + 1} x {2 * GameWindow.StreamingRadius + 1} around the mover).");
        foreach (IGrouping<int, StreamingEvent> group in record.Streaming.GroupBy(e => e.Frame))
        {
            string @in = string.Join(" ", group.Where(e => e.Loaded).Select(e => Landblock(e.LandblockId)));
            string @out = string.Join(" ", group.Where(e => !e.Loaded).Select(e => Landblock(e.LandblockId)));
            Line($"  frame {group.Key,5}: {(@in.Length > 0 ? $"loaded {@in}" : "")}{(@in.Length > 0 && @out.Length > 0 ? "; " : "")}{(@out.Length > 0 ? $"unloaded {@out}" : "")}");
        }

        foreach (string warning in record.Warnings)
        {
            Line($"Warning: {warning}");
        }

        FrameSample end = record.Final;
        Line($"Final: ({end.Position.X:F2}, {end.Position.Y:F2}, {end.Position.Z:F2}) m in 0x{end.CellId:X8}{(HoltburgWorld.CellName(end.CellId) is string name ? $" ({name})" : "")}, {(end.IsOnGround ? "on the ground" : "in the air")}.");
        foreach (string note in record.Scene.Notes)
        {
            Line($"Note: {note}");
        }

        text.AppendLine();
        Line($"SVG: {svgPath}");
        return text.ToString();
    }

    /// <summary>
    /// The chase camera (<see cref="ChaseCamera"/>, <see cref="FrameSample.Camera"/>) over the walk's frames (the start
    /// left out): how often its boom was pulled in, by how much at most, slid or boxed in, and with the player indoors
    /// how often its eye was outdoors; then, per leg that pulled it in, its frames (how many, first and last), by how
    /// much at most, and what the boom met, by kind.
    /// </summary>
    private static void AddCamera(StringBuilder text, WalkRecord record)
    {
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));
        FrameSample[] frames = [.. record.Samples.Where(s => s.Frame > 0)];
        FrameSample[] pulled = [.. frames.Where(s => s.Camera.PulledIn)];
        string most = "";
        if (pulled.Length > 0)
        {
            FrameSample worst = pulled.MaxBy(s => s.Camera.PulledInBy);
            int leg = LegOf(record, worst.Frame);
            most = string.Create(CultureInfo.InvariantCulture, $", by at most {worst.Camera.PulledInBy:F2} m (frame {worst.Frame}{(leg > 0 ? $", leg {leg}" : "")})");
        }

        int outdoors = frames.Count(s => CellIds.IsIndoor(s.CellId) && !CellIds.IsIndoor(s.Camera.EyeCellId));
        Line($"Camera: a chase camera (a {ChaseCamera.ViewerRadius} m sphere on a boom from a pivot {ChaseCamera.PivotHeight} m above the feet, {ChaseCamera.BoomBack} m back and {ChaseCamera.BoomUp} m up, {ChaseCamera.BoomLength:F2} m, at least {ChaseCamera.MinBoom} m; passing creatures, the player and open doors): pulled in at {FrameCount(pulled.Length)} of {frames.Length}{most}; slid along what it met at {FrameCount(frames.Count(s => s.Camera.Slid))}; boxed in at {FrameCount(frames.Count(s => s.Camera.Overlapping))}; eye outdoors with the player indoors at {FrameCount(outdoors)}.");
        if (pulled.Length == 0)
        {
            return;
        }

        Line($"Camera pulled in, per leg (the other legs: never):");
        int number = 1;
        foreach (LegResult leg in record.Legs)
        {
            FrameSample[] inLeg = [.. pulled.Where(s => s.Frame >= leg.FirstFrame && s.Frame <= leg.LastFrame)];
            if (inLeg.Length > 0)
            {
                string met = string.Join(", ", inLeg.GroupBy(s => (s.Camera.Met, s.Camera.MetId)).OrderByDescending(g => g.Count())
                    .Select(g => string.Create(CultureInfo.InvariantCulture, $"{g.Count()} × {Describe(g.Key.Met)} 0x{g.Key.MetId:X8}{Named(record, g.Key.Met, g.Key.MetId)}")));
                Line($"  leg {number}: {FrameCount(inLeg.Length)} (frames {inLeg[0].Frame}-{inLeg[^1].Frame}), by at most {inLeg.Max(s => s.Camera.PulledInBy):F2} m; met {met}");
            }

            number++;
        }
    }

    /// <summary>The scene's pointer rays (<see cref="Pointer"/>, <see cref="WalkRecord.Pointers"/>): each one's start, direction and what it met.</summary>
    private static void AddPointers(StringBuilder text, WalkRecord record)
    {
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));
        if (record.Pointers.Count == 0)
        {
            return;
        }

        Line($"Pointer rays (radius 0, at most {Pointer.MaxLength} m, stopping at everything but the player):");
        foreach ((ScenePointer ray, int frame, PointerHit hit) in record.Pointers)
        {
            string what = hit.Hit
                ? string.Create(CultureInfo.InvariantCulture, $"{Describe(hit.Kind)} 0x{hit.Id:X8}{Named(record, hit.Kind, hit.Id)} at ({hit.Point.X:F2}, {hit.Point.Y:F2}, {hit.Point.Z:F2}), {hit.Distance:F2} m, in cell 0x{hit.CellId:X8}")
                : "nothing";
            Line($"  {ray.Name} (after leg {ray.AfterLeg}, frame {frame}): from ({ray.From.X:F2}, {ray.From.Y:F2}, {ray.From.Z:F2}) towards ({ray.Towards.X:F2}, {ray.Towards.Y:F2}, {ray.Towards.Z:F2}): {what}.");
        }
    }

    /// <summary>" (name)" for what a cast met: a mover's (<see cref="MoverName"/>), or an object's or a Holtburg cell's the host names; else empty.</summary>
    private static string Named(WalkRecord record, SurfaceKind kind, uint id) =>
        (kind == SurfaceKind.Mover ? MoverName(record, id) : HoltburgWorld.ObjectName(id) ?? HoltburgWorld.CellName(id)) is string name ? $" ({name})" : "";

    /// <summary>Short text for a kind of surface a cast met.</summary>
    public static string Describe(SurfaceKind kind) => kind switch
    {
        SurfaceKind.Terrain => "terrain",
        SurfaceKind.CellFloor => "cell floor",
        SurfaceKind.CellWall => "cell wall",
        SurfaceKind.CellCeiling => "cell ceiling",
        SurfaceKind.ObjectFloor => "object floor",
        SurfaceKind.ObjectWall => "object wall",
        SurfaceKind.BuildingShell => "building shell",
        SurfaceKind.Cylinder => "cylinder",
        SurfaceKind.FloorEdge => "floor edge",
        SurfaceKind.Mover => "mover",
        _ => "land not loaded",
    };

    /// <summary>
    /// The objects: the sets the scene registered and how many objects each landblock got, then the
    /// object floors the mover stood on and the object walls it met, by object id, with the frames and legs.
    /// </summary>
    private static void AddObjects(StringBuilder text, WalkRecord record)
    {
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));
        IReadOnlyList<string> sets = record.Scene.Objects ?? [];
        string registered = string.Join(", ", record.Streaming.Where(e => e.Loaded && e.Objects > 0).GroupBy(e => e.LandblockId)
            .Select(g => string.Create(CultureInfo.InvariantCulture, $"{g.First().Objects} in 0x{Landblock(g.Key)}")));
        Line($"Objects: {(sets.Count == 0 ? "none chosen" : string.Join(", ", sets))} (world {record.Scene.World}){(registered.Length > 0 ? $"; registered {registered}" : "")}.");
        Line($"Object floors stood on: {DescribeObjects(record, s => s.FloorObjectId, _ => null)}.");
        Line($"Object walls met: {DescribeObjects(record, s => s.WallObjectId, s => s.Refusal is ResolveOutcome refusal ? Describe(refusal) : "slid")}.");
    }
}
