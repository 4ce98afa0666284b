using System.Globalization;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.Movement;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;
using static AcDream.App.Tests.CellGeometry;
using static AcDream.Testing.ReferenceBody;

namespace AcDream.App.Tests;

/// <summary>The chase camera over the default walk and at the cottage's walls and west door.</summary>
public sealed class ChaseCameraTests(DefaultWalk walk) : IClassFixture<DefaultWalk>
{
    private const uint Holtburg = HoltburgWorld.Holtburg;
    private const uint MainRoom = 0xA9B40143u;

    /// <summary>The least distance allowed from the eye's centre to a wall polygon: the viewer sphere's radius, less 1 mm.</summary>
    private const double Clearance = ChaseCamera.ViewerRadius - 1e-3;

    /// <summary>The building a Holtburg cell is in: 0x14 for the cottage (0x0140..0x014F), 0x17 for building B (0x0170..0x0175); 0 outdoors.</summary>
    private static uint Building(uint cellId) => CellIds.IsIndoor(cellId) ? (cellId & 0xFFFFu) >> 4 : 0u;

    private static string Show(FrameSample s) => string.Create(CultureInfo.InvariantCulture,
        $"frame {s.Frame}: feet {s.Position} in 0x{s.CellId:X8}, pivot {s.Camera.Pivot} in 0x{s.Camera.PivotCellId:X8}, eye {s.Camera.Eye} in 0x{s.Camera.EyeCellId:X8}, length {s.Camera.Length:F4}, pulled {s.Camera.PulledIn} by {s.Camera.Met} 0x{s.Camera.MetId:X8} at {s.Camera.Contact}, slid {s.Camera.Slid}, overlapping {s.Camera.Overlapping}");

    [Fact]
    public void DefaultWalk_TheBoomIsNeverShorterThanHalfAMetreNorLongerThanItsFullLength()
    {
        FrameSample[] samples = [.. walk.Record.Samples];
        string[] bad = [.. samples.Where(s => s.Camera.Length < ChaseCamera.MinBoom - 1e-4f || s.Camera.Length > ChaseCamera.BoomLength + 1e-4f
            || MathF.Abs(Vector3.Distance(s.Camera.Pivot, s.Camera.Eye) - s.Camera.Length) > 1e-4f || s.Camera.Overlapping).Select(Show)];

        bad.Should().BeEmpty($"the eye is {ChaseCamera.MinBoom}..{ChaseCamera.BoomLength} m from the pivot, never boxed in");
        samples.Should().OnlyContain(s => s.Camera.Pivot == s.Position + new Vector3(0f, 0f, ChaseCamera.PivotHeight), "no ceiling is nearer than the pivot's 1.5 m over the walk");
        samples.Count(s => s.Camera.PulledIn).Should().BeGreaterThan(300, "walls, ceilings, the closed door, the needle's slope and the small building's shell pull it in");
        samples.Count(s => s.Camera.Slid).Should().BeGreaterThan(0, "something nearer than half a metre, at least once");
        foreach (FrameSample s in samples.Where(s => !s.Camera.PulledIn))
        {
            s.Camera.Length.Should().Be(ChaseCamera.BoomLength, Show(s));
        }
    }

    [Fact]
    public void DefaultWalk_TheEyeIsNeverInsideACellsWall()
    {
        List<(uint CellId, Vec3[] Polygon)> walls = Walls(walk.World);
        walls.Should().HaveCountGreaterThan(200, "the 22 cells' walls and ceilings");
        var near = new List<string>();
        double least = double.PositiveInfinity;
        foreach (FrameSample s in walk.Record.Samples)
        {
            Vec3 eye = V(s.Camera.Eye);
            foreach ((uint cell, Vec3[] polygon) in walls)
            {
                double d = Distance(eye, polygon);
                least = Math.Min(least, d);
                if (d < Clearance)
                {
                    near.Add(string.Create(CultureInfo.InvariantCulture, $"{d:F5} m from a wall of 0x{cell:X8}: {Show(s)}"));
                }
            }
        }

        near.Should().BeEmpty($"the eye's sphere ({ChaseCamera.ViewerRadius} m) stays clear of every cell's walls; the least distance was {least:F5} m");
    }

    [Fact]
    public void DefaultWalk_WithThePlayerIndoorsTheEyeIsInItsBuildingOrWentOutThroughItsDoorway()
    {
        List<(uint CellId, Vec3[] Polygon)> doorways = OutdoorPortals(walk.World);
        doorways.Select(d => d.CellId).Should().Contain([0xA9B40145u, 0xA9B4014Fu, 0xA9B40170u], "the west door, the north door, B's north door");
        var bad = new List<string>();
        int outThroughDoor = 0, indoors = 0;
        foreach (FrameSample s in walk.Record.Samples.Where(s => CellIds.IsIndoor(s.CellId)))
        {
            indoors++;
            CameraView c = s.Camera;
            if (CellIds.IsIndoor(c.EyeCellId))
            {
                if (Building(c.EyeCellId) != Building(s.CellId))
                {
                    bad.Add($"in another building: {Show(s)}");
                }

                continue;
            }

            // Outdoors: the eye's path (pivot to eye, by the contact when it slid) passed out through a doorway of the player's building.
            Vec3[] path = c.Slid ? [V(c.Pivot), V(c.Contact), V(c.Eye)] : [V(c.Pivot), V(c.Eye)];
            bool through = doorways.Any(d => Building(d.CellId) == Building(s.CellId) && path.Zip(path.Skip(1)).Any(leg => Crosses(leg.First, leg.Second, d.Polygon)));
            if (!through)
            {
                bad.Add($"outdoors, not through a doorway: {Show(s)}");
            }

            outThroughDoor++;
        }

        bad.Should().BeEmpty($"of {indoors} frames indoors");
        outThroughDoor.Should().BeGreaterThan(0, "the boom goes out through the open west door while the player passes it facing in");
        walk.Summary.Split(System.Environment.NewLine).Should().ContainSingle(l => l.StartsWith("Camera: ", StringComparison.Ordinal))
            .Which.Should().Contain($"eye outdoors with the player indoors at {outThroughDoor} frame");
    }

    [Fact]
    public void DefaultWalk_TheSummaryGivesThePullsInAllAndPerLeg()
    {
        WalkRecord record = walk.Record;
        string[] lines = walk.Summary.Split(System.Environment.NewLine);
        FrameSample[] frames = [.. record.Samples.Where(s => s.Frame > 0)];
        FrameSample[] pulled = [.. frames.Where(s => s.Camera.PulledIn)];
        FrameSample worst = pulled.MaxBy(s => s.Camera.PulledInBy);
        int worstLeg = 1 + record.Legs.ToList().FindIndex(l => worst.Frame >= l.FirstFrame && worst.Frame <= l.LastFrame);
        int outdoors = frames.Count(s => CellIds.IsIndoor(s.CellId) && !CellIds.IsIndoor(s.Camera.EyeCellId));

        lines.Should().ContainSingle(l => l.StartsWith("Camera: ", StringComparison.Ordinal)).Which.Should().Be(string.Create(CultureInfo.InvariantCulture,
            $"Camera: a chase camera (a 0.3 m sphere on a boom from a pivot 1.5 m above the feet, 2.5 m back and 0.75 m up, 2.61 m, at least 0.5 m; passing creatures, the player and open doors): pulled in at {pulled.Length} frames of {frames.Length}, by at most {worst.Camera.PulledInBy:F2} m (frame {worst.Frame}, leg {worstLeg}); slid along what it met at {frames.Count(s => s.Camera.Slid)} frames; boxed in at 0 frames; eye outdoors with the player indoors at {outdoors} frames."));
        lines.Should().ContainSingle(l => l == "Camera pulled in, per leg (the other legs: never):");
        for (int i = 0; i < record.Legs.Count; i++)
        {
            LegResult leg = record.Legs[i];
            FrameSample[] inLeg = [.. pulled.Where(s => s.Frame >= leg.FirstFrame && s.Frame <= leg.LastFrame)];
            string[] legLines = [.. lines.Where(l => l.StartsWith($"  leg {i + 1}: ", StringComparison.Ordinal))];
            if (inLeg.Length == 0)
            {
                legLines.Should().BeEmpty($"leg {i + 1} never pulled the boom in");
                continue;
            }

            legLines.Should().ContainSingle($"leg {i + 1} pulled it in at {inLeg.Length} frames").Which.Should().StartWith(string.Create(CultureInfo.InvariantCulture,
                $"  leg {i + 1}: {inLeg.Length} frame{(inLeg.Length == 1 ? "" : "s")} (frames {inLeg[0].Frame}-{inLeg[^1].Frame}), by at most {inLeg.Max(s => s.Camera.PulledInBy):F2} m; met "));
        }

        // The closed west door pulls it in from inside (leg 7, as it closes behind, and leg 9) and from outside (leg 29).
        foreach (int leg in (int[])[7, 9, 29])
        {
            lines.Single(l => l.StartsWith($"  leg {leg}: ", StringComparison.Ordinal)).Should().Contain("× mover 0x7A9B4145 (cottage west door)");
        }
    }

    [Theory]
    [InlineData("the main room's east wall", 142.5f, 10f, -1f, 0f)]
    [InlineData("the main room's north-east corner", 142.5f, 13.5f, -0.7071f, -0.7071f)]
    public void BackingAgainstAWall_PullsTheBoomInToHalfAMetreSlidingClearOfTheWall(string wall, float x, float y, float normalX, float normalY)
    {
        HoltburgWorld world = new();
        Scene scene = SceneReader.Parse(string.Create(CultureInfo.InvariantCulture, $$"""
            { "name": "backing", "start": { "position": [134, 5.15], "heading": 90 }, "effects": "player",
              "legs": [ { "name": "in", "to": [137.2, 5.15] }, { "name": "room", "to": [139, 10] },
                        { "name": "back into {{wall}}", "to": [{{x}}, {{y}}], "backward": true, "seconds": 3 } ] }
            """), "test");
        WalkRecord record = SceneRunner.Run(scene, world);
        LegResult backing = record.Legs[2];
        FrameSample[] frames = [.. record.Samples.Where(s => s.Frame >= backing.FirstFrame && s.Frame <= backing.LastFrame)];
        FrameSample end = frames[^1];
        List<(uint CellId, Vec3[] Polygon)> walls = Walls(world);

        backing.Reached.Should().BeFalse($"the point is past the wall; ended at {end.Position}");
        end.CellId.Should().Be(MainRoom);
        end.Camera.PulledIn.Should().BeTrue(Show(end));
        end.Camera.Slid.Should().BeTrue($"the wall is 0.48 m behind the pivot, nearer than {ChaseCamera.MinBoom} m along the boom: {Show(end)}");
        end.Camera.Length.Should().BeApproximately(ChaseCamera.MinBoom, 1e-3f, Show(end));
        end.Camera.PulledInBy.Should().BeApproximately(ChaseCamera.BoomLength - ChaseCamera.MinBoom, 1e-3f, Show(end));
        end.Camera.EyeCellId.Should().Be(MainRoom, Show(end));
        end.Camera.Met.Should().Be(SurfaceKind.CellWall, Show(end));
        Vector2 away = new Vector2(end.Camera.Eye.X - end.Camera.Pivot.X, end.Camera.Eye.Y - end.Camera.Pivot.Y);
        Vector2.Dot(away, new Vector2(normalX, normalY)).Should().BeLessThan(0f, $"the eye is still behind the pivot, towards the wall: {Show(end)}");
        foreach (FrameSample s in frames)
        {
            s.Camera.Length.Should().BeGreaterThanOrEqualTo(ChaseCamera.MinBoom - 1e-4f, Show(s));
            double least = walls.Min(w => Distance(V(s.Camera.Eye), w.Polygon));
            least.Should().BeGreaterThanOrEqualTo(Clearance, $"clear of the walls: {Show(s)}");
        }
    }

    [Fact]
    public void ACastOutThroughTheWestDoor_IsClearWhenItIsOpenAndStoppedByItWhenClosed()
    {
        (GameWindow window, WorldDoor door) = CottageWithItsWestDoor();
        using (window)
        {
            PhysicsEngine engine = window.Physics;
            var camera = new ChaseCamera(engine, SceneRunner.PlayerId);
            var from = new Vector3(138.5f, 5.15f, 95.25f); // in the main room, level with the doorway's middle (z 94..96.5)
            var to = new Vector3(133.5f, 5.15f, 95.25f);   // outdoors, west of the doorway
            var feet = new Vector3(138.5f, 5.15f, 94f);
            const float east = MathF.PI / 2f;              // facing east: the boom points west, out through the doorway

            CastHit closed = engine.Cast(from, MainRoom, to, camera.Options);
            CameraView closedView = camera.Update(feet, MainRoom, east);
            engine.Movers.Open(door.Id);
            window.CommitMovers();
            CastHit open = engine.Cast(from, MainRoom, to, camera.Options);
            CameraView openView = camera.Update(feet, MainRoom, east);

            (closed.Hit, closed.Kind, closed.Id).Should().Be((true, SurfaceKind.Mover, door.Id), $"the closed door stops it: {closed}");
            closed.Position.X.Should().BeApproximately(136.552f + ChaseCamera.ViewerRadius, 1e-3f, $"at the slab's east face (x 136.552) plus the radius: {closed}");
            closed.CellId.Should().Be(MainRoom, $"the sphere's centre is still in the main room (east of x 136.7): {closed}");
            (open.Hit, open.Fraction, open.Position).Should().Be((false, 1f, to), $"the open door lets it pass: {open}");
            CellIds.IsIndoor(open.CellId).Should().BeFalse($"it ends outdoors: 0x{open.CellId:X8}");

            (closedView.PulledIn, closedView.Met, closedView.MetId).Should().Be((true, SurfaceKind.Mover, door.Id), $"{closedView}");
            closedView.Eye.X.Should().BeGreaterThanOrEqualTo(136.552f + ChaseCamera.ViewerRadius, $"the eye is on the room's side of the closed door: {closedView}");
            openView.PulledIn.Should().BeFalse($"the boom reaches out through the open door: {openView}");
            openView.Length.Should().Be(ChaseCamera.BoomLength);
            CellIds.IsIndoor(openView.EyeCellId).Should().BeFalse($"the eye is outdoors, 0x{openView.EyeCellId:X8}: {openView}");
            openView.Eye.X.Should().BeLessThan(136.3f, $"west of the doorway: {openView}");
        }
    }

    [Fact]
    public void Update_AllocatesNothingPerFrame()
    {
        (GameWindow window, WorldDoor door) = CottageWithItsWestDoor();
        using (window)
        {
            var camera = new ChaseCamera(window.Physics, SceneRunner.PlayerId);

            // The player's places over the default walk, each facing the way its eye looked (any heading would do).
            FrameSample[] samples = [.. walk.Record.Samples.Where(s => CellIds.LandblockOf(s.CellId) == Holtburg)];
            float[] headings = [.. samples.Select(s => MathF.Atan2(s.Camera.Pivot.X - s.Camera.Eye.X, s.Camera.Pivot.Y - s.Camera.Eye.Y))];
            int pulled = 0;
            void Frames()
            {
                pulled = 0;
                for (int i = 0; i < samples.Length; i++)
                {
                    pulled += camera.Update(samples[i].Position, samples[i].CellId, headings[i]).PulledIn ? 1 : 0;
                }
            }

            Frames(); // warm up: the JIT, and the thread's one record of the movers a cast near one reads
            long start = GC.GetAllocatedBytesForCurrentThread();
            Frames();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - start;

            allocated.Should().Be(0, $"{samples.Length} frames of the camera (with the door as a mover, {pulled} pulled in)");
            samples.Length.Should().BeGreaterThan(4000);
            pulled.Should().BeGreaterThan(100, "the frames include pulls and slides");
            door.Id.Should().Be(ObjectPlacements.CottageWestDoor);
        }
    }

    [Theory]
    [InlineData("a wall behind", 0f, -1.0f, 0f, 3f, 1)]                // 0.5 m from the south wall, facing north
    [InlineData("a corner behind", 1.0f, 1.0f, 225f, 3f, 2)]            // 0.5 m from the east and north walls, facing south-west
    [InlineData("a corner under a low ceiling", 1.0f, 1.0f, 225f, 2f, 3)] // the same, the ceiling 0.5 m over the pivot
    public void Update_InAClosedRoom_SlidesAlongWhatItMetToHalfAMetreOrIsBoxedIn(string what, float x, float y, float headingDegrees, float ceiling, int surfaces)
    {
        // A closed 3 m square room (cell-local x, y −1.5..1.5, floor z 0) at (50, 50, 10), over terrain at 0 m.
        var origin = new Vector3(50f, 50f, 10f);
        var box = new CellBuilder(0xA9B40100u, origin);
        box.Floor(-1.5f, -1.5f, 1.5f, 1.5f, 0f);
        box.Physics([.. CellBuilder.Square(-1.5f, -1.5f, 1.5f, 1.5f, ceiling).Reverse()]);
        box.Physics(new(-1.5f, -1.5f, 0f), new(1.5f, -1.5f, 0f), new(1.5f, -1.5f, ceiling), new(-1.5f, -1.5f, ceiling));
        box.Physics(new(1.5f, -1.5f, 0f), new(1.5f, 1.5f, 0f), new(1.5f, 1.5f, ceiling), new(1.5f, -1.5f, ceiling));
        box.Physics(new(1.5f, 1.5f, 0f), new(-1.5f, 1.5f, 0f), new(-1.5f, 1.5f, ceiling), new(1.5f, 1.5f, ceiling));
        box.Physics(new(-1.5f, 1.5f, 0f), new(-1.5f, -1.5f, 0f), new(-1.5f, -1.5f, ceiling), new(-1.5f, 1.5f, ceiling));
        PhysicsEngine engine = TestWorlds.Engine(TestWorlds.Heights((_, _) => 0), box.Build());
        var camera = new ChaseCamera(engine);
        Vector3 feet = origin + new Vector3(x, y, 0f);

        CameraView view = camera.Update(feet, box.CellId, headingDegrees * MathF.PI / 180f);

        string shown = $"{what}: {view}";
        (view.PulledIn, view.Met, view.MetId).Should().Be((true, SurfaceKind.CellWall, box.CellId), shown);
        view.Pivot.Should().Be(feet + new Vector3(0f, 0f, ChaseCamera.PivotHeight), shown);
        view.EyeCellId.Should().Be(box.CellId, shown);
        view.Length.Should().BeApproximately(ChaseCamera.MinBoom, 1e-4f, shown);
        Vector3 local = view.Eye - origin;
        float[] clearances = [local.X + 1.5f, 1.5f - local.X, local.Y + 1.5f, 1.5f - local.Y, local.Z, ceiling - local.Z];
        if (surfaces < 3)
        {
            (view.Slid, view.Overlapping).Should().Be((true, false), shown);
            clearances.Should().OnlyContain(c => c >= ChaseCamera.ViewerRadius + ChaseCamera.Skin - 1e-4f, $"off every wall by the radius and the skin: {string.Join(", ", clearances)}; {shown}");
            local.Z.Should().BeGreaterThan(ChaseCamera.PivotHeight + 0.3f, $"it slid up {(surfaces == 1 ? "the wall" : "the corner")}: {shown}");
            if (surfaces == 2)
            {
                (1.5f - local.X).Should().BeApproximately(ChaseCamera.ViewerRadius + ChaseCamera.Skin, 2e-3f, $"in the corner, against the east wall: {shown}");
                (1.5f - local.Y).Should().BeApproximately(ChaseCamera.ViewerRadius + ChaseCamera.Skin, 2e-3f, $"and the north wall: {shown}");
            }
        }
        else
        {
            (view.Slid, view.Overlapping).Should().Be((false, true), $"the corner's walls and the ceiling leave no way: {shown}");
            Vector3 along = Vector3.Normalize(new Vector3(MathF.Sqrt(0.5f) * ChaseCamera.BoomBack, MathF.Sqrt(0.5f) * ChaseCamera.BoomBack, ChaseCamera.BoomUp));
            Vector3.Distance(view.Eye, view.Pivot + (along * ChaseCamera.MinBoom)).Should().BeLessThan(1e-4f, $"half a metre along the boom: {shown}");
        }
    }

    /// <summary>A window with Holtburg's landblock, the default scene's objects and the cottage's west door (closed), committed.</summary>
    private static (GameWindow Window, WorldDoor Door) CottageWithItsWestDoor()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage", "small-building", "cellar-stairs"]);
        WorldDoor door = world.Doors["cottage-west"];
        var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue(error);
        window.AddMover(door.Id, door.Shape, door.Position, door.CellId, door.Orientation, MoverState.Door);
        window.CommitMovers();
        return (window, door);
    }
}
