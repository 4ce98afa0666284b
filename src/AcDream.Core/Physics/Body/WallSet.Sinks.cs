using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.Body;

// WallSet, what its sources are handed to: a lister of the sources, a sweeper of walls and a riser into ceilings.
internal ref partial struct WallSet
{
    /// <summary>What the sources found are handed to, one encoded source at a time (slot, object bit, index).</summary>
    private interface ISourceSink
    {
        /// <summary>Takes a source; false to stop.</summary>
        bool Add(int source);
    }

    /// <summary>Lists the sources in a span; stops when one more does not fit.</summary>
    private ref struct Lister(Span<int> storage) : ISourceSink
    {
        private readonly Span<int> _storage = storage;

        public int Count;

        public readonly int this[int i] => _storage[i];

        public readonly bool Contains(int source) => _storage[..Count].Contains(source);

        public bool Add(int source)
        {
            if (Count == _storage.Length)
            {
                return false;
            }

            _storage[Count++] = source;
            return true;
        }
    }

    /// <summary>Sweeps a body move against each source's walls (a cell's with its objects', or an outdoor object's).</summary>
    private ref struct Sweeper(ref Neighbourhood lands, LandblockEntry entry, in BodyMove move, ref WallHit hit, Vector2 lo, Vector2 hi, float moverDrop) : ISourceSink
    {
        private readonly ref Neighbourhood _lands = ref lands;
        private readonly ref readonly BodyMove _move = ref move;
        private readonly ref WallHit _hit = ref hit;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Add(int source)
        {
            int slot = /* Stryker disable once Bitwise : a source is never negative */ source >> SlotShift, index = source & (MoverBit - 1);
            Vector2 offset = Offset(slot);
            Vector2 boxLo = lo - offset, boxHi = hi - offset;
            if ((source & MoverBit) != 0)
            {
                MoverFrame movers = _lands.Movers!;
                _hit.Current = new WallSource(SurfaceKind.Mover, movers.Ids[index]);
                MoverSolid.Sweep(movers.Walls[index], offset, boxLo, boxHi, _move with { ZLow = _move.ZLow - moverDrop }, ref _hit);
                return true;
            }

            LandblockEntry of = /* Stryker disable once Conditional : the landblock in slot Own is the entry's own */ slot == Own ? entry : _lands.Get(entry.X + (slot / 3) - 1, entry.Y + (slot % 3) - 1)!;
            if ((source & ObjectBit) != 0)
            {
                ObjectSurface outdoors = of.OutdoorObjects[index];
                _hit.Current = WallSource.Of(outdoors);
                BodySweep.SweepWalls(outdoors.Walls, offset, boxLo, boxHi, in _move, ref _hit);
                return true;
            }

            CellSurface cell = of.Cells[index];
            _hit.Current = new WallSource(SurfaceKind.CellWall, cell.CellId);
            ulong near = cell.OpenFloor is OpenFloor open ? open.WallsNear(boxLo, boxHi) : ulong.MaxValue;
            BodySweep.SweepWalls(cell.Walls, near, offset, new WallBox(boxLo, boxHi, _move.ZLow, _move.ZHigh), in _move, ref _hit);
            foreach (ObjectSurface o in cell.Objects)
            {
                _hit.Current = WallSource.Of(o);
                BodySweep.SweepWalls(o.Walls, offset, boxLo, boxHi, in _move, ref _hit);
            }

            return true;
        }
    }

    /// <summary>Reads each source's surfaces overhead for a rising body (a cell's walls and floors with its objects', or an outdoor object's); or, <c>steep</c>, the steep faces under a falling one.</summary>
    private ref struct Riser(ref Neighbourhood lands, LandblockEntry entry, in BodyRise rise, ref CeilingHit hit, bool steep = false) : ISourceSink
    {
        private readonly ref Neighbourhood _lands = ref lands;
        private readonly ref readonly BodyRise _rise = ref rise;
        private readonly ref CeilingHit _hit = ref hit;

        public bool Add(int source)
        {
            int slot = /* Stryker disable once Bitwise : a source is never negative */ source >> SlotShift, index = source & (MoverBit - 1);
            Vector2 offset = Offset(slot);
            if ((source & MoverBit) != 0)
            {
                MoverFrame movers = _lands.Movers!;
                _hit.Current = new WallSource(SurfaceKind.Mover, movers.Ids[index]);
                if (steep)
                {
                    Overhead.Tops(movers.Walls[index], offset, in _rise, ref _hit);
                }
                else
                {
                    Overhead.Walls(movers.Walls[index], offset, in _rise, ref _hit);
                }

                return true;
            }

            LandblockEntry of = /* Stryker disable once Conditional : the landblock in slot Own is the entry's own */ slot == Own ? entry : _lands.Get(entry.X + (slot / 3) - 1, entry.Y + (slot % 3) - 1)!;
            if ((source & ObjectBit) != 0)
            {
                Read(of.OutdoorObjects[index], offset);
                return true;
            }

            CellSurface cell = of.Cells[index];
            _hit.Current = new WallSource(SurfaceKind.CellWall, cell.CellId);
            if (steep)
            {
                Overhead.Steep(cell.Walls, offset, in _rise, ref _hit);
            }
            else
            {
                Overhead.Walls(cell.Walls, offset, in _rise, ref _hit);
                if (/* Stryker disable once Equality : a floor level with the top is no ceiling over it, which Overhead.Floors tests again */ cell.FloorZMax > _rise.Top)
                {
                    Overhead.Floors(cell.Floors, offset, in _rise, ref _hit); // (a cell's floors all below the head are no ceiling)
                }
            }

            foreach (ObjectSurface o in cell.Objects)
            {
                Read(o, offset);
            }

            return true;
        }

        private readonly void Read(ObjectSurface o, Vector2 offset)
        {
            _hit.Current = WallSource.Of(o);
            if (steep)
            {
                Overhead.Steep(o.Walls, offset, in _rise, ref _hit);
                return;
            }

            Overhead.Walls(o.Walls, offset, in _rise, ref _hit);
            if (/* Stryker disable once Equality : a floor level with the top is no ceiling over it, which Overhead.Floors tests again */ o.BoundsMax.Z > _rise.Top)
            {
                Overhead.Floors(o.Floors, offset, in _rise, ref _hit);
            }
        }
    }
}
