using System.Globalization;
using System.Numerics;
using System.Text;
using AcDream.Core.Physics;
using AcDream.App.Movement;
using AcDream.App.World;

namespace AcDream.App.Scenes;

/// <summary>The summary a person reads after a run: cells, refusals, airborne frames, streaming, the end.</summary>
internal static class WalkReport
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

    /// <summary>
    /// The movers: the movers the player's moves touched, by id; the doors' states as committed, frame by frame; the
    /// creatures, how far they walked, how often one was held back, and the closest any two movers' centres came.
    /// </summary>
    private static void AddMovers(StringBuilder text, WalkRecord record)
    {
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));
        var parts = new List<string>();
        foreach (IGrouping<uint, MoverTouch> group in record.Touches.GroupBy(t => t.MoverId))
        {
            int stopped = group.Count(t => t.Stopped);
            parts.Add(string.Create(CultureInfo.InvariantCulture,
                $"0x{group.Key:X8} {MoverName(record, group.Key)}: {FrameCount(group.Count())}{(stopped > 0 ? $" ({stopped} × stopped or slid the player)" : "")}, frames {group.First().Frame}-{group.Last().Frame}, {Legs(record, group.Select(t => t.Frame))}"));
        }

        Line($"Movers met: {(parts.Count == 0 ? "none" : string.Join("; ", parts))}.");
        foreach (IGrouping<uint, DoorChange> door in record.DoorChanges.GroupBy(d => d.DoorId))
        {
            var states = door.ToList();
            var changes = new List<string>();
            for (int i = 0; i < states.Count; i++)
            {
                int leg = LegOf(record, states[i].Frame);
                string held = states[i].State == DoorState.Closing && i + 1 < states.Count
                    ? string.Create(CultureInfo.InvariantCulture, $", held {states[i + 1].Frame - states[i].Frame} frames")
                    : "";
                changes.Add(string.Create(CultureInfo.InvariantCulture, $"{states[i].State.ToString().ToLowerInvariant()} at frame {states[i].Frame}{(leg > 0 ? $" (leg {leg})" : "")}{held}"));
            }

            Line($"Door 0x{door.Key:X8} {MoverName(record, door.Key)}: {string.Join("; ", changes)}.");
        }

        IReadOnlyList<CreaturePath> creatures = record.Creatures;
        if (creatures.Count == 0)
        {
            return;
        }

        int standing = creatures.Count(c => c.Creature.Wander <= 0f);
        float walked = 0f;
        foreach (CreaturePath creature in creatures)
        {
            for (int i = 1; i < creature.Samples.Count; i++)
            {
                walked += creature.Samples[i].Frame == creature.Samples[i - 1].Frame + 1 ? Vector3.Distance(creature.Samples[i].Position, creature.Samples[i - 1].Position) : 0f;
            }
        }

        Line($"Creatures: {creatures.Count} ({creatures.Count - standing} wandering, {standing} standing), ids 0x{creatures[0].Id:X8}..0x{creatures[^1].Id:X8}, each an upright cylinder of radius {MoverBody.Player.Radius} m, {MoverBody.Player.Height} m tall; walked {walked:F1} m in all; held back {creatures.Sum(c => c.HeldBack)} frames (a creature's answer ended inside a mover that had moved first that frame).");
        (float between, uint a, uint b, int atFrame) = record.ClosestCreatures();
        (float toPlayer, uint c, int playerFrame) = record.ClosestToPlayer();
        Line($"Closest centres: two creatures {between:F3} m apart (0x{a:X8} and 0x{b:X8} at frame {atFrame}); a creature and the player {toPlayer:F3} m (0x{c:X8} at frame {playerFrame}).");
        foreach (CreaturePath creature in creatures)
        {
            foreach ((int frame, uint landblock) in creature.Removed)
            {
                Line($"Creature 0x{creature.Id:X8} left with its landblock 0x{Landblock(landblock)} at frame {frame}.");
            }
        }
    }

    /// <summary>A leg's movers touched, when it touched any: each id with its name and frames.</summary>
    private static string DescribeLegMovers(WalkRecord record, LegResult leg)
    {
        var parts = record.Touches.Where(t => t.Frame >= leg.FirstFrame && t.Frame <= leg.LastFrame).GroupBy(t => t.MoverId)
            .Select(g => string.Create(CultureInfo.InvariantCulture, $"0x{g.Key:X8} {MoverName(record, g.Key)} ({FrameCount(g.Count())})")).ToList();
        return parts.Count == 0 ? "" : "; movers met: " + string.Join(", ", parts);
    }

    /// <summary>"1 frame", "n frames".</summary>
    private static string FrameCount(int frames) => string.Create(CultureInfo.InvariantCulture, $"{frames} frame{(frames == 1 ? "" : "s")}");

    /// <summary>A mover's short name: the door's, "creature", "player", or "mover".</summary>
    private static string MoverName(WalkRecord record, uint id) =>
        HoltburgWorld.ObjectName(id) ?? (id == SceneRunner.PlayerId ? "player" : record.Creatures.Any(c => c.Id == id) ? "creature" : "mover");

    /// <summary>The number (1-based) of the leg frame <paramref name="frame"/> belongs to; 0 before the first.</summary>
    private static int LegOf(WalkRecord record, int frame) =>
        1 + record.Legs.ToList().FindIndex(l => frame >= l.FirstFrame && frame <= l.LastFrame);

    /// <summary>"leg n" or "legs n, m" for the legs of <paramref name="frames"/>.</summary>
    private static string Legs(WalkRecord record, IEnumerable<int> frames)
    {
        var legs = frames.Select(f => LegOf(record, f)).Where(l => l > 0).Distinct().ToList();
        return $"leg{(legs.Count == 1 ? "" : "s")} {string.Join(", ", legs)}";
    }

    /// <summary>Per object id (nonzero <paramref name="idOf"/>): its frames, first and last, the outcomes (<paramref name="kindOf"/>) and the legs.</summary>
    private static string DescribeObjects(WalkRecord record, Func<FrameSample, uint> idOf, Func<FrameSample, string?> kindOf)
    {
        var parts = new List<string>();
        foreach (IGrouping<uint, FrameSample> group in record.Samples.Where(s => idOf(s) != 0).GroupBy(idOf))
        {
            string name = World.HoltburgWorld.ObjectName(group.Key) is string n ? $" {n}" : "";
            string kinds = string.Join(", ", group.Select(kindOf).Where(k => k is not null).GroupBy(k => k).Select(k => $"{k.Count()} × {k.Key}"));
            var legs = new List<int>();
            foreach (FrameSample sample in group)
            {
                int leg = 1 + record.Legs.ToList().FindIndex(l => sample.Frame >= l.FirstFrame && sample.Frame <= l.LastFrame);
                if (leg > 0 && !legs.Contains(leg))
                {
                    legs.Add(leg);
                }
            }

            parts.Add(string.Create(CultureInfo.InvariantCulture,
                $"0x{group.Key:X8}{name}: {group.Count()} frames{(kinds.Length > 0 ? $" ({kinds})" : "")}, frames {group.First().Frame}-{group.Last().Frame}, leg{(legs.Count == 1 ? "" : "s")} {string.Join(", ", legs)}"));
        }

        return parts.Count == 0 ? "none" : string.Join("; ", parts);
    }

    /// <summary>Short text for the opt-in effects a scene uses.</summary>
    private static string DescribeEffects(MovementOptions effects)
    {
        var on = new List<string>();
        if (effects.StepDownHeight is float down)
        {
            on.Add(FormattableString.Invariant($"step down {down} m (falls under gravity)"));
        }

        if (effects.WalkableSlope)
        {
            on.Add("walkable slope");
        }

        if (effects.SweepStepLength is float sweep)
        {
            on.Add(FormattableString.Invariant($"swept in {sweep} m sub-steps"));
        }

        if (effects.DoorsOnly)
        {
            on.Add("doors only");
        }

        if (effects.Body is MoverBody body)
        {
            on.Add(FormattableString.Invariant($"a body (an upright cylinder of radius {body.Radius} m, {body.Height} m tall) that slides along walls"));
            if (effects.Vertical)
            {
                on.Add("vertical motion (jumps and falls swept: ceilings stop them, the first floor lands them)");
            }

            if (effects.Footing)
            {
                on.Add("footing under the body (half its radius past an edge)");
            }

            if (effects.EdgeSlide)
            {
                on.Add("edge slide");
            }
        }

        return on.Count == 0 ? "none (the spec's literal engine)" : string.Join(", ", on);
    }

    /// <summary>
    /// A leg's slides, from the engine's normals (<see cref="ResolveResult.SurfaceNormal"/>, one per
    /// slid frame, in frame order): along walls (a horizontal normal, pointing at the mover) and, with
    /// walkable slope, along the contour of a slope too steep to climb (the slope's normal, with a Z).
    /// Each kind gives its frames and its normal, or, when its normals differ (a rounded corner), how
    /// many differ and the first and last, each rounded to 0.01.
    /// </summary>
    public static string DescribeSlides(IReadOnlyList<Vector3> normals)
    {
        var parts = new List<string>();
        foreach (bool walls in (ReadOnlySpan<bool>)[true, false])
        {
            var distinct = new List<string>();
            int frames = 0;
            foreach (Vector3 n in normals)
            {
                if (IsWall(n) != walls)
                {
                    continue;
                }

                frames++;
                string text = walls
                    ? FormattableString.Invariant($"({Round(n.X):F2}, {Round(n.Y):F2})")
                    : FormattableString.Invariant($"({Round(n.X):F2}, {Round(n.Y):F2}, {Round(n.Z):F2})");
                if (!distinct.Contains(text))
                {
                    distinct.Add(text);
                }
            }

            if (frames > 0)
            {
                string along = walls ? (distinct.Count == 1 ? "a wall" : "walls") : (distinct.Count == 1 ? "a slope's contour" : "slopes' contours");
                parts.Add(distinct.Count == 1
                    ? $"{frames} × along {along}, normal {distinct[0]}"
                    : $"{frames} × along {along}, {distinct.Count} normals from {distinct[0]} to {distinct[^1]}");
            }
        }

        return string.Join(", ", parts);
    }

    /// <summary>A slide's normal is a wall's when it is horizontal (the engine's walls are); a slope's has a Z.</summary>
    private static bool IsWall(Vector3 normal) => normal.Z == 0f;

    /// <summary>Rounded to 0.01, without a negative zero.</summary>
    private static float Round(float value) => MathF.Round(value, 2) + 0f;

    /// <summary>Short text for one of the engine's outcomes, 1:1 (the engine's reason, not a guess).</summary>
    public static string Describe(ResolveOutcome outcome) => outcome switch
    {
        ResolveOutcome.StepTooHigh => FormattableString.Invariant($"step too high (> {PlayerMovementMode.StepUpHeight} m)"),
        ResolveOutcome.SlopeTooSteep => "slope too steep",
        ResolveOutcome.Wall => "wall",
        ResolveOutcome.OuterWall => "outer wall",
        ResolveOutcome.UnloadedAhead => "unloaded land ahead",
        ResolveOutcome.EdgeOfWorld => "edge of the world",
        ResolveOutcome.Moved => "moved",
        ResolveOutcome.Slid => "slid",
        ResolveOutcome.Held => "held (land not loaded)",
        ResolveOutcome.Edge => "held at an edge",
        ResolveOutcome.Ceiling => "head hit",
        _ => outcome.ToString(),
    };

    /// <summary>A leg's jumps, head hits, landings and edge slides, when it had any.</summary>
    private static string DescribeAir((int Jumps, int HeadHits, int Landings, int EdgeSlides) air)
    {
        var parts = new List<string>();
        void Add(int count, string what)
        {
            if (count > 0)
            {
                parts.Add(string.Create(CultureInfo.InvariantCulture, $"{count} × {what}"));
            }
        }

        Add(air.Jumps, "jump");
        Add(air.HeadHits, "head hit");
        Add(air.Landings, "landing");
        Add(air.EdgeSlides, "edge slide");
        return parts.Count == 0 ? "" : "; " + string.Join(", ", parts);
    }

    /// <summary>The engine's outcomes that are refusals (<see cref="ResolveResult.IsRefused"/>), in the engine's order.</summary>
    private static IEnumerable<ResolveOutcome> Refusals =>
        Enum.GetValues<ResolveOutcome>().Where(o => (default(ResolveResult) with { Outcome = o }).IsRefused);

    /// <summary>A landblock as the summary prints it: <c>XXYY</c>.</summary>
    private static string Landblock(uint id) =>
        string.Create(CultureInfo.InvariantCulture, $"{CellIds.LandblockX(id):X2}{CellIds.LandblockY(id):X2}");

    private static IEnumerable<string> Seams(IReadOnlyList<(int Frame, uint CellId)> visits, int first, int last)
    {
        for (int k = first + 1; k <= last; k++)
        {
            if (CellIds.LandblockOf(visits[k].CellId) != CellIds.LandblockOf(visits[k - 1].CellId))
            {
                yield return string.Create(CultureInfo.InvariantCulture, $"0x{Landblock(visits[k - 1].CellId)} -> 0x{Landblock(visits[k].CellId)} at frame {visits[k].Frame}");
            }
        }
    }
}
